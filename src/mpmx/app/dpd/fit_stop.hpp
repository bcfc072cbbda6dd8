#pragma once
// Ctrl-C or SIGTERM during `mpmx fit-dpd`. A fit's stages are parallel loops over
// densities that run for minutes, so it stops at once instead of at a stage's end: a
// watcher thread sees the signal, writes OUT/checkpoint.bin with the stages finished so
// far (kept here by the fit after each), OUT/run.json with "status": "interrupted", says
// how to resume, and ends the process with exit status 130. `fit-dpd --resume` continues
// from the last finished stage (the stage it stopped in runs again whole). The fit's other
// work (OUT/.staging) is removed; nothing else in OUT changes. The watcher is stopped before the finished fit is moved into OUT.
#include <atomic>
#include <mutex>
#include <string>
#include <thread>

#include <toml++/toml.h>

#include "mpmx/app/dpd/fit_checkpoint.hpp"
#include "mpmx/core/interrupt.hpp"

namespace mpmx::app::dpd {

class FitStop {
 public:
  // `deck_text`: the deck's canonical text, `densities` its count (the checkpoint's frame).
  // `owner`: the run's owner text (io/run_manifest.hpp), for the files it writes into OUT.
  FitStop(std::string deck_file, std::string out, const toml::table& deck_echo, std::string deck_text,
          std::size_t densities, std::string owner);
  ~FitStop();
  FitStop(const FitStop&) = delete;
  FitStop& operator=(const FitStop&) = delete;

  // The stages finished so far: what a signal from now on saves.
  void keep(const FitProgress& p);
  // Stops as a signal would (for tests: a stop after a known stage).
  [[noreturn]] void stop();

 private:
  std::string deck_file_, out_, deck_text_, owner_;
  std::size_t densities_;
  toml::table deck_echo_;
  std::mutex mutex_;
  FitProgress kept_;
  InterruptGuard guard_;
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

}  // namespace mpmx::app::dpd
