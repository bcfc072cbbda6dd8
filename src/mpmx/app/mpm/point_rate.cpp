#include "mpmx/app/mpm/point_rate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/step_limit.hpp"
#include "mpmx/mpm/step.hpp"

namespace mpmx::app {

namespace {

// Below the 8,192 points from which a run steps on threads: the figure is one core's.
constexpr double kPoints = 4000, kNodes = 20000;
constexpr double kMostPointsBuilt = 1e6;  // the coarse copy's whole grid filled: an upper bound
constexpr double kSeconds = 0.1;
constexpr int kMostSteps = 2000;

template <int Dim>
double time_steps(const MpmConfig& c) {
  mpm::State<Dim> s = make_state<Dim>(c, true, 1);
  const double points = static_cast<double>(s.particles.size());
  if (!(points > 0)) return 0.0;
  const auto dt = [&] { return c.cfl_dt ? mpm::step_limit(s, {c.cfl, c.max_volume_strain}).dt : c.dt; };
  mpm::step(s, dt());  // the first step sizes the scratch arrays: not timed
  const auto t0 = std::chrono::steady_clock::now();
  double seconds = 0;
  int n = 0;
  while (n < kMostSteps && seconds < kSeconds) {
    mpm::step(s, dt());
    ++n;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return seconds > 0 ? points * n / seconds : 0.0;
}

}  // namespace

double measure_point_steps_per_second(const MpmConfig& c, double points, double subpoints, double nodes) {
  if (c.material.spec && c.material.spec->atoms_per_point() > 0) return 0.0;
  MpmConfig r = c;
  r.convergence_levels = 1;
  // Coarser cells over the same domain and bodies: a few thousand integration points of the
  // same kind (and a grid of at most a few times as many nodes, where bodies fill little
  // of it). Sub-points too many for even a coarse copy: not timed.
  if (!(subpoints * 8 <= kPoints)) return 0.0;
  const double f = std::min({1.0, std::pow(kPoints / subpoints / points, 1.0 / c.dim),
                             std::pow(kNodes / nodes, 1.0 / c.dim)});
  for (int d = 0; d < c.dim; ++d) r.cells_all[d] = std::max(2, static_cast<int>(std::lround(c.cells_all[d] * f)));
  r.cells = c.dim == 1 ? std::max(2, static_cast<int>(std::lround(c.cells * f))) : r.cells_all[0];
  // The copy's points from the counts, before it is built: a grid of two cells still
  // holds per_cell^D points a cell (per_cell = 10^6 in 2-D: 10^12, minutes of placing).
  double coarse = subpoints;
  for (int d = 0; d < c.dim; ++d)
    coarse *= static_cast<double>(c.dim == 1 ? r.cells : r.cells_all[d]) *
              static_cast<double>(c.dim == 1 ? c.per_cell : c.per_cell_all[d]);
  if (!(coarse <= kMostPointsBuilt)) return 0.0;
  try {
    switch (c.dim) {
      case 1: return time_steps<1>(r);
      case 2: return time_steps<2>(r);
      default: return time_steps<3>(r);
    }
  } catch (const std::exception&) {
    return 0.0;  // the coarse copy cannot run (a body that no longer holds a point, ...)
  }
}

}  // namespace mpmx::app
