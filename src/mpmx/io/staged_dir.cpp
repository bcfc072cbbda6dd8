#include "mpmx/io/staged_dir.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"

namespace mpmx::io {

namespace fs = std::filesystem;

std::string StagedDir::staging_of(const std::string& out) { return (fs::path(out) / ".staging").string(); }

StagedDir::StagedDir(std::string out, bool keep) : out_(std::move(out)), staging_(staging_of(out_)), keep_(keep) {
  std::error_code ec;
  out_existed_ = fs::exists(out_, ec);
  // Every command's --out: a file there is the user's, never a folder to write into.
  if (out_existed_ && !fs::is_directory(out_, ec))
    throw InputError(fmt::format("--out {}: exists and is not a directory", out_));
  if (!keep) fs::remove_all(staging_, ec);
  // Made now, before the run's work: a folder that cannot be (read-only, a name too long)
  // is bad input, said in words; a run that never writes removes it again.
  if (fs::create_directories(staging_, ec); ec || !fs::is_directory(staging_, ec)) {
    const auto e = static_cast<std::errc>(ec.value());
    const std::string why =
        e == std::errc::no_such_file_or_directory ? "a folder on its path cannot be made there"
        : e == std::errc::permission_denied || e == std::errc::operation_not_permitted
            ? "permission denied: the folder it goes in cannot be written"
            : path_problem(staging_, ec);
    throw InputError(fmt::format("--out {}: cannot make the output folder: {}", short_path(out_), why));
  }
}

void StagedDir::publish() {
  std::error_code ec;
  if (fs::is_directory(staging_, ec)) {
    for (const auto& e : fs::directory_iterator(staging_)) {
      const fs::path to = fs::path(out_) / e.path().filename();
      // A folder (vtk/) replaces the earlier run's whole; a file is renamed over.
      if (e.is_directory() && fs::exists(to)) fs::remove_all(to);
      fs::rename(e.path(), to, ec);
      if (ec) throw RunError(fmt::format("cannot move {} to {}: {}", e.path().string(), to.string(), ec.message()));
    }
    fs::remove_all(staging_, ec);
  }
  published_ = true;
}

StagedDir::~StagedDir() {
  if (published_ || keep_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (!out_existed_ && fs::is_empty(out_, ec) && !ec) fs::remove(out_, ec);
}

}  // namespace mpmx::io
