#include "mpmx/mpm/solve.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace mpmx::mpm {

namespace {

// 1-D: one vectorised pass over the nodes (the fused path's solve).
void solve_1d(Grid<1>& g, const Boundaries& bc, double t, double dt, Tallies& tally) {
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
  // Held ends (a prescribed velocity, or a piston while it pushes): v^n at t, v^L at
  // t + dt. What they add is tallied.
  auto hold = [&](std::size_t i, int face) {
    const BoundarySide& side = bc.face[face];
    if (!side.holds(0, face, vL[i], t + dt)) return;
    v[i] = side.velocity(t, 0, face);
    vL[i] = side.velocity(t + dt, 0, face);
    const double impulse = m[i] * (vL[i] - v[i]) - dt * f[i];
    tally.boundary_impulse[0] += impulse;
    tally.boundary_work += impulse * 0.5 * (vL[i] + v[i]);
  };
  hold(i0, 0);
  hold(i1, 1);
  if (force_abs > 0.0) tally.max_force_sum = std::max(tally.max_force_sum, std::abs(force_sum) / force_abs);
  tally.node_mass = mass_sum;
}

}  // namespace

template <int Dim>
void solve_grid(Grid<Dim>& g, const Boundaries& bc, double t, double dt, Tallies& tally, int threads) {
  if constexpr (Dim == 1) {
    solve_1d(g, bc, t, dt, tally);
  } else {
    // Over lines of nodes along x, taken by threads; each line's sums kept apart and added
    // in line order, so the tallies do not depend on the thread count.
    // Only the span's nodes (active_lines.hpp): elsewhere mass and force are zero.
    const std::size_t lines = g.lines();
    constexpr int kSums = 1 + 2 * Dim;  // mass, force sum and |force| per component
    std::vector<double> sums(lines * kSums, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t l = 0; l < lines; ++l) {
      const std::size_t i0 = g.index(g.line_first(l));
      double* sum = &sums[l * kSums];
      for (int x = g.span_lo[l]; x <= g.span_hi[l]; ++x) {
        const std::size_t i = i0 + static_cast<std::size_t>(x);
        sum[0] += g.mass[i];
        for (int a = 0; a < Dim; ++a) {
          sum[1 + a] += g.force[a][i];
          sum[1 + Dim + a] += std::abs(g.force[a][i]);
        }
      }
    }
    double mass_sum = 0.0;
    std::array<double, Dim> force_sum{}, force_abs{};
    for (std::size_t l = 0; l < lines; ++l) {
      mass_sum += sums[l * kSums];
      for (int a = 0; a < Dim; ++a) {
        force_sum[a] += sums[l * kSums + 1 + a];
        force_abs[a] += sums[l * kSums + 1 + Dim + a];
      }
    }
    std::size_t nodes = 1;
    for (int d = 0; d < Dim; ++d) nodes *= static_cast<std::size_t>(g.cells[d] + 1);
    const double tiny = 1e-14 * mass_sum / static_cast<double>(nodes);
    // What the faces add, per line: the impulse per component and the work.
    constexpr int kFace = Dim + 1;
    std::vector<double> added_by_faces(lines * kFace, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t l = 0; l < lines; ++l) {
      std::array<int, Dim> idx = g.line_first(l);
      const std::size_t i0 = g.index(idx);
      bool line_on_face = false;  // most lines are inside: no face loop for their inner nodes
      for (int d = 1; d < Dim; ++d) line_on_face = line_on_face || idx[d] == 0 || idx[d] == g.cells[d];
      double* face_sum = &added_by_faces[l * kFace];
      for (int x = g.span_lo[l]; x <= g.span_hi[l]; ++x) {
        idx[0] = x;
        const std::size_t i = i0 + static_cast<std::size_t>(x);
        const bool on_face = line_on_face || x == 0 || x == g.cells[0];
        const double m = g.mass[i];
        const bool has = m > tiny;
        const double r = 1.0 / (has ? m : 1.0);
        for (int a = 0; a < Dim; ++a) {
          const double vi = g.momentum[a][i] * r;
          double v = has ? vi : 0.0, vL = has ? vi + dt * g.force[a][i] * r : 0.0;
          // A node on a face with a condition on component a (a piston's while it
          // pushes); at edges and corners the first face that holds the component sets it.
          for (int f = 0; on_face && f < 2 * Dim; ++f) {
            const int axis = f / 2;
            const bool on = (f % 2 == 0) ? idx[axis] == 0 : idx[axis] == g.cells[axis];
            const BoundarySide& side = bc.face[f];
            if (!on || !side.holds(a, f, vL, t + dt)) continue;
            const double vn = side.velocity(t, a, f), vl = side.velocity(t + dt, a, f);
            // What the face adds to the material's momentum: m (v^L - v^n) - dt f.
            const double added = m * (vl - vn) - dt * g.force[a][i];
            if (has) {
              face_sum[a] += added;
              face_sum[Dim] += added * 0.5 * (vl + vn);
            }
            v = vn;
            vL = vl;
            break;
          }
          g.velocity[a][i] = v;
          g.velocity_L[a][i] = vL;
        }
      }
    }
    for (std::size_t l = 0; l < lines; ++l) {
      for (int a = 0; a < Dim; ++a) tally.boundary_impulse[a] += added_by_faces[l * kFace + a];
      tally.boundary_work += added_by_faces[l * kFace + Dim];
    }
    double fs = 0.0, fa = 0.0;
    for (int a = 0; a < Dim; ++a) fs += force_sum[a] * force_sum[a], fa += force_abs[a];
    if (fa > 0.0) tally.max_force_sum = std::max(tally.max_force_sum, std::sqrt(fs) / fa);
    tally.node_mass = mass_sum;
  }
}

template <int Dim>
void work_and_volumes(Particles<Dim>& p, double dt, bool small_strain, bool track_domain, Tallies& tally,
                      int threads) {
  const std::size_t n = p.size();
  double w = 0.0;
  if constexpr (Dim == 1) {
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
    if (track_domain) {
      double* __restrict len = p.length[0].data();
#pragma omp simd
      for (std::size_t q = 0; q < n; ++q) len[q] *= 1.0 + dt * L[q];
    }
  } else {
    const bool tensor_q = !p.viscous[0].empty();
    // Each chunk of particles sums its own work, the chunks are added in order: the same
    // total for any thread count.
    constexpr std::size_t chunk = 1024;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    std::vector<double> part(chunks, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t ck = 0; ck < chunks; ++ck)
    for (std::size_t q = ck * chunk; q < std::min(n, (ck + 1) * chunk); ++q) {
      double work = 0.0, div = 0.0;
      for (int a = 0; a < Dim; ++a) {
        div += p.grad_v[a * Dim + a][q];
        for (int b = 0; b < Dim; ++b) {
          double s = p.stress[a * Dim + b][q] - (a == b ? p.viscous_pressure[q] : 0.0);
          if (tensor_q) s += p.viscous[a * Dim + b][q];
          work += s * p.grad_v[a * Dim + b][q];
        }
      }
      part[ck] += (small_strain ? p.volume0[q] : p.volume[q]) * work;
      p.volume[q] *= 1.0 + dt * div;
      if (track_domain) {  // r_b += dt L r_b for every domain vector b
        double r[Dim][Dim];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) r[a][b] = p.length[a * Dim + b][q];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            double lr = 0.0;
            for (int c = 0; c < Dim; ++c) lr += p.grad_v[a * Dim + c][q] * r[c][b];
            p.length[a * Dim + b][q] = r[a][b] + dt * lr;
          }
      }
    }
    for (double x : part) w += x;
  }
  tally.stress_work += dt * w;
}

template void solve_grid<1>(Grid<1>&, const Boundaries&, double, double, Tallies&, int);
template void solve_grid<2>(Grid<2>&, const Boundaries&, double, double, Tallies&, int);
template void solve_grid<3>(Grid<3>&, const Boundaries&, double, double, Tallies&, int);
template void work_and_volumes<1>(Particles<1>&, double, bool, bool, Tallies&, int);
template void work_and_volumes<2>(Particles<2>&, double, bool, bool, Tallies&, int);
template void work_and_volumes<3>(Particles<3>&, double, bool, bool, Tallies&, int);

}  // namespace mpmx::mpm
