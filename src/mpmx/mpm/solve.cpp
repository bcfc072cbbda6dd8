#include "mpmx/mpm/solve.hpp"

#include <algorithm>
#include <cmath>

namespace mpmx::mpm {

void solve_grid(Grid<1>& g, const Boundaries& bc, double t, double dt, Tallies& tally) {
  const int N = g.cells[0];
  const std::size_t i0 = g.index1(0), i1 = g.index1(N);
  double mass_sum = 0.0, force_sum = 0.0, force_abs = 0.0;
  auto& m = g.mass;
  auto& mom = g.momentum[0];
  auto& v = g.velocity[0];
  auto& vL = g.velocity_L[0];
  auto& f = g.force[0];
  for (std::size_t i = i0; i <= i1; ++i) {
    mass_sum += m[i];
    force_sum += f[i];
    force_abs += std::abs(f[i]);
  }
  // Nodes without mass (outside the material) stay at rest.
  const double tiny = 1e-14 * mass_sum / (N + 1);
  for (std::size_t i = i0; i <= i1; ++i) {
    if (m[i] > tiny) {
      v[i] = mom[i] / m[i];
      vL[i] = v[i] + dt * f[i] / m[i];
    } else {
      v[i] = vL[i] = 0.0;
    }
  }
  // Prescribed ends: v^n at t, v^L at t + dt. What they add is tallied.
  auto hold = [&](std::size_t i, const BoundarySide& side) {
    if (!side.prescribed()) return;
    v[i] = side.velocity(t);
    vL[i] = side.velocity(t + dt);
    const double impulse = m[i] * (vL[i] - v[i]) - dt * f[i];
    tally.boundary_impulse += impulse;
    tally.boundary_work += impulse * 0.5 * (vL[i] + v[i]);
  };
  hold(i0, bc.left);
  hold(i1, bc.right);
  if (force_abs > 0.0) tally.max_force_sum = std::max(tally.max_force_sum, std::abs(force_sum) / force_abs);
  tally.node_mass = mass_sum;
}

void update_volumes(Particles<1>& p, double dt, bool track_length) {
  const std::size_t n = p.size();
  for (std::size_t q = 0; q < n; ++q) p.volume[q] *= 1.0 + dt * p.grad_v[0][q];
  if (track_length)
    for (std::size_t q = 0; q < n; ++q) p.length[0][q] *= 1.0 + dt * p.grad_v[0][q];
}

void account_stress_work(const Particles<1>& p, double dt, bool small_strain, Tallies& tally) {
  double w = 0.0;
  const std::size_t n = p.size();
  const std::vector<double>& vol = small_strain ? p.volume0 : p.volume;
  for (std::size_t q = 0; q < n; ++q)
    w += vol[q] * (p.stress[0][q] - p.viscous_pressure[q]) * p.grad_v[0][q];
  tally.stress_work += dt * w;
}

}  // namespace mpmx::mpm
