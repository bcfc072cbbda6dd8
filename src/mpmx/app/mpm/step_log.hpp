#pragma once
// The steps a dt = "cfl" run took: each step's length and what set it (mpm/step_limit.hpp,
// or the record time it landed on), for the progress line, the summary and run.json's
// `time_steps`. A checkpoint carries it whole, so a resumed run reports the whole run.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/mpm/step_limit.hpp"

namespace mpmx::app {

class StepLog {
 public:
  // Step `step` ending at `time` took dt; `limit` is what the state allowed (its dt may be
  // longer: the step was cut to whole MD steps or to land on a record time, `by`).
  void add(std::int64_t step, double time, double dt, mpm::StepLimiter by, const mpm::StepLimit& limit);
  bool empty() const { return dt_.empty(); }
  // "dt 0.0043 (cfl)": the last step, for the progress line.
  std::string last() const;
  // "steps 0.0012 / 0.0045 / 0.0050 (smallest / median / largest); set by cfl 412, ..."
  std::string summary() const;
  toml::table record() const;
  void save(CheckpointOut& out) const;
  void load(CheckpointIn& in);

 private:
  std::vector<double> dt_;
  std::vector<std::int64_t> by_;
  std::array<std::int64_t, mpm::kStepLimiters> count_{};
  // The shortest step the state set (not a record time's landing): where, and why.
  std::int64_t tight_step_ = -1;
  double tight_time_ = 0.0;
  mpm::StepLimit tight_;
};

}  // namespace mpmx::app
