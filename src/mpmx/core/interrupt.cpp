#include "mpmx/core/interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace mpmx {

namespace {

volatile std::sig_atomic_t g_signals = 0;

// Only async-signal-safe calls here: write(2), signal, raise.
extern "C" void on_interrupt(int sig) {
  g_signals = g_signals + 1;
  if (g_signals == 2) {
    // `timeout` and a batch system send SIGTERM to the process and then to its group: a
    // second signal is taken as the same request, so the checkpoint under way ends whole.
    static const char msg[] = "\nmpmx: stopping at the next record with a checkpoint; a third signal kills at once\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, msg, sizeof msg - 1);
  } else if (g_signals >= 3) {
    std::signal(sig, SIG_DFL);  // the escape: the third one kills
    std::raise(sig);
  }
}

}  // namespace

InterruptGuard::InterruptGuard(bool active) : active_(active), previous_(SIG_DFL), previous_term_(SIG_DFL) {
  if (!active_) return;
  g_signals = 0;
  previous_ = std::signal(SIGINT, on_interrupt);
  previous_term_ = std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  if (!active_) return;
  std::signal(SIGINT, previous_);
  std::signal(SIGTERM, previous_term_);
}

bool InterruptGuard::interrupted() { return g_signals != 0; }

}  // namespace mpmx
