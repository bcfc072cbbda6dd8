#include "mpmx/core/progress.hpp"

#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

namespace mpmx {

Progress::Progress(std::string label, std::int64_t total, bool quiet)
    : label_(std::move(label)), total_(total), active_(!quiet && isatty(fileno(stderr))),
      start_(clock::now()), last_(start_) {}

void Progress::update(std::int64_t done) {
  if (!active_) return;
  const auto now = clock::now();
  if (now - last_ < std::chrono::milliseconds(300)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double frac = total_ > 0 ? static_cast<double>(done) / total_ : 1.0;
  const double eta = frac > 0 ? elapsed * (1.0 - frac) / frac : 0.0;
  fmt::print(stderr, "\r{}: {:5.1f}%  step {}/{}  elapsed {:.1f} s  ETA {:.1f} s   ", label_,
             100.0 * frac, done, total_, elapsed, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (!active_) return;
  const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
  fmt::print(stderr, "\r{}: done, {} steps in {:.2f} s{:30}\n", label_, total_, elapsed, "");
}

}  // namespace mpmx
