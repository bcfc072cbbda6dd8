#include "mpmx/mpm/solve.hpp"

#include <algorithm>
#include <cmath>

namespace mpmx::mpm {

void solve_grid(Grid<1>& g, const Boundaries& bc, double t, double dt, Tallies& tally) {
  const int N = g.cells[0];
  const std::size_t i0 = g.index1(0), i1 = g.index1(N);
  double mass_sum = 0.0, force_sum = 0.0, force_abs = 0.0;
  const double* __restrict m = g.mass.data();
  const double* __restrict mom = g.momentum[0].data();
  double* __restrict v = g.velocity[0].data();
  double* __restrict vL = g.velocity_L[0].data();
  const double* __restrict f = g.force[0].data();
#pragma omp simd reduction(+ : mass_sum, force_sum, force_abs)
  for (std::size_t i = i0; i <= i1; ++i) {
    mass_sum += m[i];
    force_sum += f[i];
    force_abs += std::abs(f[i]);
  }
  // Nodes without mass (outside the material) stay at rest. Branch-free (the divisor is
  // 1 where unused) so that the loop vectorises; one divide per node.
  const double tiny = 1e-14 * mass_sum / (N + 1);
#pragma omp simd
  for (std::size_t i = i0; i <= i1; ++i) {
    const bool has = m[i] > tiny;
    const double r = 1.0 / (has ? m[i] : 1.0);
    const double vi = mom[i] * r;
    v[i] = has ? vi : 0.0;
    vL[i] = has ? vi + dt * f[i] * r : 0.0;
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

void work_and_volumes(Particles<1>& p, double dt, bool small_strain, bool track_length,
                      Tallies& tally) {
  const std::size_t n = p.size();
  double w = 0.0;
  double* __restrict V = p.volume.data();
  const double* __restrict V0 = p.volume0.data();
  const double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  const double* __restrict L = p.grad_v[0].data();
#pragma omp simd reduction(+ : w)
  for (std::size_t q = 0; q < n; ++q) {
    w += (small_strain ? V0[q] : V[q]) * (sig[q] - qv[q]) * L[q];
    V[q] *= 1.0 + dt * L[q];
  }
  if (track_length) {
    double* __restrict len = p.length[0].data();
#pragma omp simd
    for (std::size_t q = 0; q < n; ++q) len[q] *= 1.0 + dt * L[q];
  }
  tally.stress_work += dt * w;
}

}  // namespace mpmx::mpm
