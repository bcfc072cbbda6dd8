#include "mpmx/app/dpd/fit_stop.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/exit_codes.hpp"
#include "mpmx/io/atomic_file.hpp"
#include "mpmx/io/folder_lock.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/io/staged_dir.hpp"

namespace mpmx::app::dpd {

FitStop::FitStop(std::string deck_file, std::string out, const toml::table& deck_echo, std::string deck_text,
                 std::size_t densities, std::string owner)
    : deck_file_(std::move(deck_file)), out_(std::move(out)), deck_text_(std::move(deck_text)),
      owner_(std::move(owner)),
      densities_(densities), deck_echo_(deck_echo), guard_(true) {
  watcher_ = std::thread([this] {
    while (!done_.load()) {
      if (InterruptGuard::interrupted()) stop();
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
  });
}

FitStop::~FitStop() {
  done_ = true;
  watcher_.join();
}

void FitStop::keep(const FitProgress& p) {
  const std::lock_guard<std::mutex> lock(mutex_);
  kept_ = p;
}

void FitStop::stop() {
  const std::lock_guard<std::mutex> lock(mutex_);  // the fit keeps no stage while this writes
  const std::string checkpoint = (std::filesystem::path(out_) / "checkpoint.bin").string();
  std::error_code ec;
  std::filesystem::create_directories(out_, ec);
  bool saved = false;
  toml::table rec{{"version", MPMX_VERSION},
                  {"command", "fit-dpd"},
                  {"status", "interrupted"},
                  {"deck_file", deck_file_},
                  {"deck", deck_echo_},
                  {"stopped", kept_.stage()}};
  try {
    if (!kept_.empty()) {
      write_fit_checkpoint(checkpoint, deck_text_, densities_, kept_);
      saved = true;
      rec.insert("checkpoint", checkpoint);
    } else {
      std::filesystem::remove(checkpoint, ec);  // an older fit's: not this one's to resume
    }
    io::write_file_atomic((std::filesystem::path(out_) / "run.json").string(), io::json_text(rec));
    io::record_written(out_, owner_, saved ? std::set<std::string>{"checkpoint.bin", "run.json"}
                                           : std::set<std::string>{"run.json"});
  } catch (const std::exception& e) {
    // The disk refused the checkpoint: the machine's failure, not an interruption to resume.
    std::fprintf(stderr, "\nmpmx: the file system failed: %s\n", e.what());
    std::fflush(stderr);
    std::_Exit(exit_code::internal);
  }
  const std::string msg =
      saved ? fmt::format("\nmpmx: interrupted: fit-dpd stopped {}; {} keeps the stages finished: continue with: "
                          "mpmx fit-dpd {} --out {} --resume\n",
                          kept_.stage(), checkpoint, deck_file_, out_)
            : fmt::format("\nmpmx: interrupted: fit-dpd stopped {}: nothing to resume; start again with: mpmx "
                          "fit-dpd {} --out {}\n",
                          kept_.stage(), deck_file_, out_);
  std::fputs(msg.c_str(), stderr);
  std::fflush(stdout);
  std::fflush(stderr);
  // _Exit runs no destructor: the staging folder (half a fit, never a result: the resume
  // starts from the checkpoint) and the folder's lock file go here, as ~StagedDir and
  // ~FolderLock would take them.
  std::filesystem::remove_all(io::StagedDir::staging_of(out_), ec);
  std::filesystem::remove(std::filesystem::path(out_) / io::FolderLock::kName, ec);
  std::_Exit(exit_code::interrupted);
}

}  // namespace mpmx::app::dpd
