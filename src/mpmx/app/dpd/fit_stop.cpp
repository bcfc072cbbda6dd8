#include "mpmx/app/dpd/fit_stop.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/exit_codes.hpp"
#include "mpmx/io/atomic_file.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/io/staged_dir.hpp"

namespace mpmx::app::dpd {

FitStop::FitStop(std::string deck_file, std::string out, const toml::table& deck_echo)
    : deck_file_(std::move(deck_file)), out_(std::move(out)), deck_echo_(deck_echo), guard_(true) {
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

void FitStop::stop() const {
  const std::string staging = io::StagedDir::staging_of(out_);
  const toml::table rec{{"version", MPMX_VERSION},
                        {"command", "fit-dpd"},
                        {"status", "interrupted"},
                        {"deck_file", deck_file_},
                        {"deck", deck_echo_},
                        {"partial_results", staging}};
  std::error_code ec;
  std::filesystem::create_directories(out_, ec);
  try {
    io::write_file_atomic((std::filesystem::path(out_) / "run.json").string(), io::json_text(rec));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mpmx: %s\n", e.what());
  }
  const std::string msg = fmt::format(
      "\nmpmx: interrupted: fit-dpd stopped; a fit cannot be resumed: its work so far is in {} (hidden, cleared by "
      "the next run); start again with: mpmx fit-dpd {} --out {}\n",
      staging, deck_file_, out_);
  std::fputs(msg.c_str(), stderr);
  std::fflush(stdout);
  std::fflush(stderr);
  std::_Exit(exit_code::interrupted);
}

}  // namespace mpmx::app::dpd
