#include "mpmx/core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

#include "mpmx/core/file_text.hpp"
#include "mpmx/core/machine.hpp"

namespace mpmx {

Progress::Progress(std::string label, std::int64_t total, bool quiet, std::int64_t from)
    : label_(escape_controls(label)),  // a case id from a deck: shown, never obeyed by the terminal
      total_(total), from_(from), active_(!quiet), terminal_(isatty(fileno(stderr))),
      start_(clock::now()), last_(start_) {}

void Progress::show_rate(double items, std::string unit) {
  items_ = items;
  unit_ = std::move(unit);
}

void Progress::update(std::int64_t done) {
  show(done, total_ > 0 ? static_cast<double>(done) / total_ : 1.0, false);
}

void Progress::update(std::int64_t done, double fraction) { show(done, fraction, true); }

void Progress::show(std::int64_t done, double frac, bool estimated) {
  if (!active_) return;
  const auto now = clock::now();
  if (now - last_ < (terminal_ ? std::chrono::milliseconds(300) : std::chrono::milliseconds(60000))) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  // An estimated total follows the steps the run has taken per fraction of it done.
  const std::int64_t total =
      estimated && frac > 0 ? std::max(done, static_cast<std::int64_t>(std::llround(done / frac))) : total_;
  const double rate = done > from_ ? (done - from_) / elapsed : 0.0;
  const double eta = rate > 0 ? (total - done) / rate : 0.0;
  const std::string shown_rate = unit_.empty() ? "" : fmt::format("  {:.3g} {}/s", items_ * rate, unit_);
  fmt::print(stderr, "{}{}: {:5.1f}%  step {}/{}{}{}{}  elapsed {}  ETA {}{}", terminal_ ? "\r" : "", label_,
             100.0 * frac, done, estimated ? "~" : "", total, note_.empty() ? "" : "  " + note_, shown_rate,
             format_duration(elapsed), format_duration(eta), terminal_ ? "   " : "\n");
  std::fflush(stderr);
}

void Progress::finish() { finish(total_); }

void Progress::finish(std::int64_t done) {
  if (!active_) return;
  const double elapsed = std::chrono::duration<double>(clock::now() - start_).count();
  if (terminal_)
    fmt::print(stderr, "\r{}: done, {} steps in {}{:30}\n", label_, done - from_, format_duration(elapsed), "");
  else if (elapsed > 60)
    fmt::print(stderr, "{}: done, {} steps in {}\n", label_, done - from_, format_duration(elapsed));
}

}  // namespace mpmx
