#include "mpmx/core/interrupt.hpp"

#include <csignal>

namespace mpmx {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int sig) {
  g_interrupted = 1;
  std::signal(sig, SIG_DFL);  // a second one kills
}

}  // namespace

InterruptGuard::InterruptGuard(bool active) : active_(active), previous_(SIG_DFL), previous_term_(SIG_DFL) {
  if (!active_) return;
  g_interrupted = 0;
  previous_ = std::signal(SIGINT, on_interrupt);
  previous_term_ = std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  if (!active_) return;
  std::signal(SIGINT, previous_);
  std::signal(SIGTERM, previous_term_);
}

bool InterruptGuard::interrupted() { return g_interrupted != 0; }

}  // namespace mpmx
