#include "mpmx/mpm/step_limit.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/boundary_speed.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/tensor_viscosity.hpp"

namespace mpmx::mpm {

const char* limiter_name(StepLimiter by) {
  switch (by) {
    case StepLimiter::cfl: return "cfl";
    case StepLimiter::viscosity: return "viscosity";
    case StepLimiter::volume_strain: return "volume_strain";
    case StepLimiter::boundary: return "boundary";
    case StepLimiter::record_time: return "record_time";
  }
  return "?";
}

namespace {

// A point's candidate: the larger key wins, the smaller point on a tie, so the winner
// does not depend on how the points were split over threads.
struct Candidate {
  double key = -1.0;
  std::int64_t point = -1;
  bool beats(const Candidate& o) const { return key > o.key || (key == o.key && point >= 0 && point < o.point); }
};

}  // namespace

template <int Dim>
StepLimit step_limit(const State<Dim>& s, const StepLimitOptions& o) {
  const auto& p = s.particles;
  const auto view = points(p);
  double h = s.grid.dx[0];
  for (int d = 1; d < Dim; ++d) h = std::min(h, s.grid.dx[d]);
  const std::int64_t n = static_cast<std::int64_t>(p.size());
  const bool tensor = s.tensor_viscosity.on, linear = s.viscosity > 0.0;
  // The viscosity's speed Q = nu / h at point q, from its last gradient and its own a.
  auto viscous_speed = [&](std::int64_t q) {
    if (!tensor && !linear) return 0.0;
    const double a = s.material->sound_speed(view, static_cast<std::size_t>(q));
    if (tensor) {
      Eigen::Matrix<double, Dim, Dim> L;
      double l = 0.0;
      for (int x = 0; x < Dim; ++x) {
        l += view.length[x][q];
        for (int y = 0; y < Dim; ++y) L(x, y) = p.grad_v[x * Dim + y][q];
      }
      return tensor_viscosity_coefficient<Dim>(L, l / Dim, a, s.tensor_viscosity.c_L, s.tensor_viscosity.c_q) / h;
    }
    double div = 0.0, l = 0.0;
    for (int d = 0; d < Dim; ++d) div += p.grad_v[d * Dim + d][q], l = std::max(l, std::abs(view.length[d][q]));
    return div < 0.0 ? s.viscosity * a * l / h : 0.0;  // q = coef rho a |D| l: nu = coef a l
  };
  Candidate fastest, straining;
  double loudest = 0.0;
#pragma omp parallel num_threads(s.threads) if (s.threads > 1)
  {
    Candidate f, st;
    double loud = 0.0;
#pragma omp for schedule(static) nowait
    for (std::int64_t q = 0; q < n; ++q) {
      double v2 = 0.0, div = 0.0;
      for (int a = 0; a < Dim; ++a) v2 += p.v[a][q] * p.v[a][q], div += p.grad_v[a * Dim + a][q];
      const double c = s.material->signal_speed(view, static_cast<std::size_t>(q)), Q = viscous_speed(q);
      // Q = 0 (no viscosity, or none acting): c itself, not sqrt(c^2).
      const Candidate mine{std::sqrt(v2) + (Q > 0.0 ? Q + std::sqrt(Q * Q + c * c) : c), q}, rate{std::abs(div), q};
      if (mine.beats(f)) f = mine;
      if (rate.beats(st)) st = rate;
      loud = std::max(loud, c);
    }
#pragma omp critical
    {
      if (f.beats(fastest)) fastest = f;
      if (st.beats(straining)) straining = st;
      loudest = std::max(loudest, loud);
    }
  }
  if (!(fastest.key > 0.0) || !std::isfinite(fastest.key))
    throw RunError(fmt::format("dt = \"cfl\": no finite wave speed in step {} (t = {})", s.step, s.time));
  StepLimit r;
  r.point = fastest.point;
  const std::size_t at = static_cast<std::size_t>(r.point);
  r.c = s.material->signal_speed(view, at);
  r.q = viscous_speed(r.point);
  r.v = 0.0;
  for (int a = 0; a < Dim; ++a) r.v += p.v[a][at] * p.v[a][at];
  r.v = std::sqrt(r.v);
  r.dt = o.cfl * h / fastest.key;
  r.by = r.q > 0.0 ? StepLimiter::viscosity : StepLimiter::cfl;
  // The boundary's largest speed over the step the points alone allow (a piston's table
  // may rise within it): its neighbours take it within the step, at the largest c.
  const double wall = boundary_speed(s.boundary, Dim, s.time, s.time + r.dt);
  if (wall > 0.0 && loudest + wall > fastest.key) {
    r.dt = o.cfl * h / (loudest + wall);
    r.by = StepLimiter::boundary, r.point = -1, r.c = loudest, r.v = wall, r.q = 0.0;
  }
  if (o.max_volume_strain > 0.0 && straining.key > 0.0 && o.max_volume_strain / straining.key < r.dt) {
    r.dt = o.max_volume_strain / straining.key;
    r.by = StepLimiter::volume_strain, r.point = straining.point, r.volume_rate = straining.key;
  }
  return r;
}

template StepLimit step_limit<1>(const State<1>&, const StepLimitOptions&);
template StepLimit step_limit<2>(const State<2>&, const StepLimitOptions&);
template StepLimit step_limit<3>(const State<3>&, const StepLimitOptions&);

}  // namespace mpmx::mpm
