#pragma once
// Ctrl-C or SIGTERM during `mpmx fit-dpd`. A fit cannot be resumed (its stages are
// parallel loops over densities that run for minutes), so it stops at once instead of at
// a step boundary: a watcher thread sees the signal, writes OUT/run.json with "status":
// "interrupted", prints how to start again and ends the process with exit status 130. The
// fit's work so far stays hidden in OUT/.staging (cleared by the next run); nothing else
// in OUT changes. The watcher is stopped before the finished fit is moved into OUT.
#include <atomic>
#include <string>
#include <thread>

#include <toml++/toml.h>

#include "mpmx/core/interrupt.hpp"

namespace mpmx::app::dpd {

class FitStop {
 public:
  FitStop(std::string deck_file, std::string out, const toml::table& deck_echo);
  ~FitStop();
  FitStop(const FitStop&) = delete;
  FitStop& operator=(const FitStop&) = delete;

 private:
  [[noreturn]] void stop() const;
  std::string deck_file_, out_;
  toml::table deck_echo_;
  InterruptGuard guard_;
  std::atomic<bool> done_{false};
  std::thread watcher_;
};

}  // namespace mpmx::app::dpd
