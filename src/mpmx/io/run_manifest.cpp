#include "mpmx/io/run_manifest.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/atomic_file.hpp"

namespace mpmx::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kHead = "mpmx-files 1";

}  // namespace

std::optional<RunManifest> read_manifest(const std::string& out) {
  const fs::path path = fs::path(out) / kManifestName;
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  std::ifstream in(path);
  std::string line;
  RunManifest m;
  if (!std::getline(in, line) || line != kHead || !std::getline(in, line) || line.rfind("run ", 0) != 0)
    throw InputError(fmt::format("{}: not an mpmx file list (its first lines are not '{}' and 'run ...'); remove it "
                                 "if the folder holds no mpmx run",
                                 path.string(), kHead));
  m.owner = line.substr(4);
  while (std::getline(in, line)) {
    // A name that leads out of the folder is never one mpmx wrote there.
    if (line.empty() || fs::path(line).is_absolute() || line.find("..") != std::string::npos)
      throw InputError(fmt::format("{}: '{}' is not a file of the folder", path.string(), line));
    m.files.insert(line);
  }
  return m;
}

void write_manifest(const std::string& out, const RunManifest& m) {
  std::string text = fmt::format("{}\nrun {}\n", kHead, m.owner);
  for (const auto& f : m.files) text += f + "\n";
  write_file_atomic((fs::path(out) / kManifestName).string(), text);
}

std::string run_owner(const std::string& command, const std::string& deck) {
  std::error_code ec;
  const fs::path abs = fs::absolute(deck, ec).lexically_normal();
  return fmt::format("{} {}", command, ec ? deck : abs.string());
}

}  // namespace mpmx::io
