#pragma once
// The fastest speed the grid's faces give their nodes over a time interval: a piston's
// (its table is piecewise linear, so the largest |v| lies at an end of the interval or at
// a time of the table) and a velocity face's (|value| + |amplitude| per component, as a
// vector). The CFL step counts it: the points beside such a face move at its speed from
// the next step on, and a step taken from the points' own speeds alone outruns them (a
// 10 km/s piston into material at rest: a Courant number past 1).
#include <algorithm>
#include <cmath>

#include "mpmx/mpm/bcs.hpp"

namespace mpmx::mpm {

inline double piston_speed_between(const Piston& p, double t0, double t1) {
  double most = std::max(std::abs(p.speed(t0)), std::abs(p.speed(t1)));
  for (std::size_t k = 0; k < p.times.size() && k < p.speeds.size(); ++k)
    if (p.times[k] > t0 && p.times[k] < t1) most = std::max(most, std::abs(p.speeds[k]));
  return most;
}

// Over the faces of a `dim`-dimensional grid, from t0 to t1.
inline double boundary_speed(const Boundaries& b, int dim, double t0, double t1) {
  double most = 0.0;
  for (int f = 0; f < 2 * dim; ++f) {
    const BoundarySide& side = b.face[f];
    if (side.type == BoundarySide::Type::piston) {
      most = std::max(most, piston_speed_between(side.piston, t0, t1));
    } else if (side.type == BoundarySide::Type::velocity) {
      double v2 = 0.0;
      for (int a = 0; a < dim; ++a) {
        const double v = std::abs(side.value[a]) + std::abs(side.amplitude[a]);
        v2 += v * v;
      }
      most = std::max(most, std::sqrt(v2));
    }
  }
  return most;
}

}  // namespace mpmx::mpm
