#pragma once
// Rows by time where the steps vary (dt = "cfl"): a row at the step that reaches or
// passes each multiple of `interval`, so that a table's spacing follows the run's time
// and not a step count estimated from its first step. Stateless (the step's start and
// end), so a resumed run takes the same rows.
#include <cmath>

namespace mpmx::app {

inline bool passes_multiple(double t0, double t1, double interval) {
  constexpr double kLanding = 1e-9;  // a step that lands on a multiple counts it
  return std::floor(t1 / interval + kLanding) > std::floor(t0 / interval + kLanding);
}

}  // namespace mpmx::app
