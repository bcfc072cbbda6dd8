#include "mpmx/app/mpm/step_log.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace mpmx::app {

using mpm::StepLimiter;

namespace {
// The median of a copy (the log keeps the steps in order).
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const std::size_t m = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m), v.end());
  if (v.size() % 2) return v[m];
  return 0.5 * (v[m] + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(m)));
}

std::string speeds(const mpm::StepLimit& l) {
  switch (l.by) {
    case StepLimiter::cfl: return fmt::format("c {:.4g} + |v| {:.4g}", l.c, l.v);
    case StepLimiter::viscosity: return fmt::format("c {:.4g}, |v| {:.4g}, viscous Q {:.4g}", l.c, l.v, l.q);
    case StepLimiter::volume_strain: return fmt::format("|tr L| {:.4g}", l.volume_rate);
    case StepLimiter::boundary: return fmt::format("c {:.4g} + the boundary's {:.4g}", l.c, l.v);
    case StepLimiter::record_time: return "";
  }
  return "";
}
}  // namespace

void StepLog::add(std::int64_t step, double time, double dt, StepLimiter by, const mpm::StepLimit& limit) {
  dt_.push_back(dt);
  by_.push_back(static_cast<std::int64_t>(by));
  ++count_[static_cast<int>(by)];
  if (by != StepLimiter::record_time && (tight_step_ < 0 || dt < tight_.dt)) {
    tight_ = limit, tight_.dt = dt;
    tight_step_ = step, tight_time_ = time;
  }
}

std::string StepLog::last() const {
  if (dt_.empty()) return "";
  return fmt::format("dt {:.4g} ({})", dt_.back(), mpm::limiter_name(static_cast<StepLimiter>(by_.back())));
}

std::string StepLog::summary() const {
  if (dt_.empty()) return "";
  std::string by;
  for (int k = 0; k < mpm::kStepLimiters; ++k)
    if (count_[k] > 0) by += fmt::format("{}{} {}", by.empty() ? "" : ", ", mpm::limiter_name(StepLimiter(k)), count_[k]);
  std::string tight;
  if (tight_step_ >= 0)
    tight = fmt::format("; the shortest the state set: {:.4g} at step {} (t = {:.6g}) by {}{}{}", tight_.dt,
                        tight_step_, tight_time_, mpm::limiter_name(tight_.by),
                        tight_.point >= 0 ? fmt::format(" at point {}", tight_.point) : "",
                        speeds(tight_).empty() ? "" : " (" + speeds(tight_) + ")");
  return fmt::format("steps {:.4g} / {:.4g} / {:.4g} (smallest / median / largest), set by {}{}",
                     *std::min_element(dt_.begin(), dt_.end()), median(dt_), *std::max_element(dt_.begin(), dt_.end()),
                     by, tight);
}

toml::table StepLog::record() const {
  toml::table t{{"steps", static_cast<std::int64_t>(dt_.size())}};
  if (dt_.empty()) return t;
  t.insert("smallest", *std::min_element(dt_.begin(), dt_.end()));
  t.insert("median", median(dt_));
  t.insert("largest", *std::max_element(dt_.begin(), dt_.end()));
  toml::table by;
  for (int k = 0; k < mpm::kStepLimiters; ++k) by.insert(mpm::limiter_name(StepLimiter(k)), count_[k]);
  t.insert("limited_by", std::move(by));
  if (tight_step_ >= 0) {
    toml::table s{{"dt", tight_.dt},          {"step", tight_step_},   {"time", tight_time_},
                  {"by", mpm::limiter_name(tight_.by)}, {"point", tight_.point}, {"wave_speed", tight_.c},
                  {"speed", tight_.v},        {"viscous_speed", tight_.q}, {"volume_rate", tight_.volume_rate}};
    t.insert("shortest_by_state", std::move(s));
  }
  return t;
}

void StepLog::save(CheckpointOut& out) const {
  out.numbers(dt_);
  out.integers(by_);
  out.integer(tight_step_);
  out.numbers({tight_time_, tight_.dt, tight_.c, tight_.v, tight_.q, tight_.volume_rate});
  out.integers({static_cast<std::int64_t>(tight_.by), tight_.point});
}

void StepLog::load(CheckpointIn& in) {
  const long long at = in.offset();
  auto dt = in.numbers();
  auto by = in.integers();
  if (by.size() != dt.size()) throw in.refuse(at, "a step log whose limiters do not match its steps");
  count_ = {};
  for (std::int64_t b : by) {
    if (b < 0 || b >= mpm::kStepLimiters) throw in.refuse(at, fmt::format("a step limiter {}", b));
    ++count_[b];
  }
  dt_ = std::move(dt), by_ = std::move(by);
  tight_step_ = in.integer();
  const auto f = in.numbers();
  const auto k = in.integers();
  if (f.size() != 6 || k.size() != 2 || k[0] < 0 || k[0] >= mpm::kStepLimiters)
    throw in.refuse(at, "a step log's shortest step of the wrong shape");
  tight_time_ = f[0], tight_.dt = f[1], tight_.c = f[2], tight_.v = f[3], tight_.q = f[4], tight_.volume_rate = f[5];
  tight_.by = static_cast<StepLimiter>(k[0]), tight_.point = k[1];
}

}  // namespace mpmx::app
