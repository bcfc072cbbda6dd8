#include "mpmx/core/interrupt.hpp"

#include <csignal>

#include "mpmx/core/ranks.hpp"

namespace mpmx {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int sig) {
  g_interrupted = 1;
  std::signal(sig, SIG_DFL);
}

}  // namespace

InterruptGuard::InterruptGuard(bool active)
    : active_(active), term_(active && ranks::active()), previous_(SIG_DFL), previous_term_(SIG_DFL) {
  if (!active_) return;
  g_interrupted = 0;
  previous_ = std::signal(SIGINT, on_interrupt);
  if (term_) previous_term_ = std::signal(SIGTERM, on_interrupt);
}

InterruptGuard::~InterruptGuard() {
  if (active_) std::signal(SIGINT, previous_);
  if (term_) std::signal(SIGTERM, previous_term_);
}

bool InterruptGuard::interrupted() { return g_interrupted != 0; }

}  // namespace mpmx
