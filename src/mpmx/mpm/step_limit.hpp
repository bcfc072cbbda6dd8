#pragma once
// The step a state allows (dt = "cfl"; theory.md, "The time step"): the least of
//   cfl h / (|v| + Q + sqrt(Q^2 + c^2))   over the points (h the smallest cell side, c
//       the point's fastest wave at its current state, Material::signal_speed, and Q the
//       artificial viscosity's speed nu / h, nu its kinematic coefficient at the point's
//       last velocity gradient: with Q = 0 the Courant condition, with c = 0 the explicit
//       limit of the viscous diffusion, h^2 / 2 nu),
//   max_volume_strain / |tr L|            over the points (L the last step's gradient),
//   cfl h / (c_max + the boundary's speed over the step) (a piston's or a velocity face's),
// each point on its own and the limiting point the first of the largest speed: the same
// for any thread count.
#include <cstdint>
#include <string>

#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

enum class StepLimiter : int { cfl = 0, viscosity = 1, volume_strain = 2, boundary = 3, record_time = 4 };
constexpr int kStepLimiters = 5;
const char* limiter_name(StepLimiter by);

struct StepLimit {
  double dt = 0.0;
  StepLimiter by = StepLimiter::cfl;
  std::int64_t point = -1;           // the point that set it (-1: the boundary, a record time)
  double c = 0.0, v = 0.0, q = 0.0;  // its wave speed, speed and viscous speed
  double volume_rate = 0.0;          // its |tr L| (volume_strain)
};

struct StepLimitOptions {
  double cfl = 0.5;
  double max_volume_strain = 0.0;  // 0: no bound
};

template <int Dim>
StepLimit step_limit(const State<Dim>& s, const StepLimitOptions& o);

// The Courant part alone at Courant number cfl (estimates, tests).
template <int Dim>
double stable_dt(const State<Dim>& s, double cfl) {
  return step_limit(s, StepLimitOptions{cfl, 0.0}).dt;
}

}  // namespace mpmx::mpm
