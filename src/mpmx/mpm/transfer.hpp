#pragma once
// Particle-to-grid and grid-to-particle transfers over a precomputed stencil
// (dissertation sec. 3.1, steps 3-10). One loop shape serves every scheme.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpmx/mpm/active_lines.hpp"
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"

namespace mpmx::mpm {

namespace detail {

// Kernels with the stencil width as a compile-time constant (W > 0) or read at run
// time (W == 0), so the common widths unroll.
// Over the particles list[0 .. count) (all, in order, when list is null).
template <int Dim, int W, bool Smooth>
void p2g_kernel(const Particles<Dim>& p, const Stencil<Dim>& st, const std::vector<double>& vol,
                Grid<Dim>& g, const std::uint32_t* list, std::size_t count) {
  const int w = W > 0 ? W : st.width;
  const bool tensor_q = !p.viscous[0].empty();  // eqs. 7.8-7.10 in use
  double* __restrict mass = g.mass.data();
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t q = list ? list[k] : k;
    const double m = p.mass[q], V = vol[q], qv = p.viscous_pressure[q];
    double mv[Dim], sig[Dim][Dim];
    for (int a = 0; a < Dim; ++a) {
      mv[a] = m * p.v[a][q];
      for (int b = 0; b < Dim; ++b) {
        double s = p.stress[a * Dim + b][q] - (a == b ? qv : 0.0);
        if (tensor_q) s += p.viscous[a * Dim + b][q];
        sig[a][b] = V * s;
      }
    }
    const std::size_t e0 = q * w;
    for (int k = 0; k < w; ++k) {
      const std::size_t e = e0 + k;
      const int i = st.node[e];
      const double S = st.S[e];
      mass[i] += m * S;
      for (int a = 0; a < Dim; ++a) {
        g.momentum[a][i] += mv[a] * S;
        double f = 0.0;
        for (int b = 0; b < Dim; ++b) f += sig[a][b] * st.G[b][e];
        g.force[a][i] -= f;
      }
      if constexpr (Smooth) {  // DDMP: T^d_j = sum_p V_p sigma_p[:, d] R_jp
        const double R = st.R[e];
        for (int c = 0; c < Dim * Dim; ++c) g.smooth_stress[c][i] += sig[c / Dim][c % Dim] * R;
      }
    }
  }
}

// Returns the sum of the new velocities and positions: finite unless something blew up
// (its rounding may depend on the threads; it is only tested for finiteness).
template <int Dim, int W, bool Smooth, bool Own>
double g2p_kernel(const Grid<Dim>& g, const Stencil<Dim>& st, double dt, bool move, double wl,
                  double wn, Particles<Dim>& p, int threads) {
  const int w = W > 0 ? W : st.width;
  const std::size_t n = p.size();
  double check = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : check) num_threads(threads) if (threads > 1)
  for (std::size_t q = 0; q < n; ++q) {
    double dv[Dim] = {}, vbar[Dim] = {}, L[Dim][Dim] = {};
    const std::size_t e0 = q * w;
    for (int k = 0; k < w; ++k) {
      const std::size_t e = e0 + k;
      const int i = st.node[e];
      const double S = st.S[e];
      for (int a = 0; a < Dim; ++a) {
        const double vl = g.velocity_L[a][i], vn = g.velocity[a][i];
        const double vg = wl * vl + wn * vn;
        dv[a] += (vl - vn) * S;
        vbar[a] += vg * S;
        // The gradient reads the distributed velocities where the small-mass distribution is on.
        const double vgrad = Own ? g.gradient_velocity[a][i] : vg;
        for (int b = 0; b < Dim; ++b) L[a][b] += vgrad * st.G[b][e];
      }
      if constexpr (Smooth) {  // DDMP: sum_j R_jp H_j
        const double R = st.R[e];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) L[a][b] += R * g.smooth_gradient[a * Dim + b][i];
      }
    }
    for (int a = 0; a < Dim; ++a) {
      p.v[a][q] += dv[a];
      if (move) p.x[a][q] += dt * vbar[a];
      check += p.v[a][q] + p.x[a][q];
      for (int b = 0; b < Dim; ++b) p.grad_v[a * Dim + b][q] = L[a][b];
    }
  }
  return check;
}

// Runs kernel(list, count) over the particles in slabs of box[Dim-1] node rows along the
// last axis, by the row of each particle's first node: two slabs of the same parity
// never touch the same node, so the even slabs scatter at once, then the odd ones. Every
// node sums its particles in the same order (slab by slab, particles in order) for any
// thread count (2-D, 3-D).
template <int Dim, class Kernel>
void scatter_in_slabs(const Grid<Dim>& g, const Stencil<Dim>& st, std::size_t n, int threads, Kernel&& kernel) {
  const int w = std::max(st.box[Dim - 1], 1);
  const std::size_t row = static_cast<std::size_t>(g.stride[Dim - 1]);
  const std::size_t slabs = g.storage / row / static_cast<std::size_t>(w) + 1;
  // The particles by slab, in index order within each: a counting sort over runs of
  // particles (each run counts, then writes after the earlier runs of its slab).
  std::vector<std::uint32_t> start(slabs + 1, 0), order(n);
  const std::size_t runs = std::max<std::size_t>(1, std::min<std::size_t>(n, static_cast<std::size_t>(threads)));
  std::vector<std::uint32_t> count(runs * slabs, 0), slab(n);
  const std::uint32_t per_slab = static_cast<std::uint32_t>(row * static_cast<std::size_t>(w));
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (std::size_t r = 0; r < runs; ++r)
    for (std::size_t q = n * r / runs; q < n * (r + 1) / runs; ++q) {
      slab[q] = static_cast<std::uint32_t>(st.node[q * st.width]) / per_slab;  // node indices fit 32 bits
      ++count[r * slabs + slab[q]];
    }
  for (std::size_t s = 0; s < slabs; ++s) {
    std::uint32_t at = start[s];
    for (std::size_t r = 0; r < runs; ++r) {
      const std::uint32_t c = count[r * slabs + s];
      count[r * slabs + s] = at;  // where run r's first particle of slab s goes
      at += c;
    }
    start[s + 1] = at;
  }
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (std::size_t r = 0; r < runs; ++r)
    for (std::size_t q = n * r / runs; q < n * (r + 1) / runs; ++q)
      order[count[r * slabs + slab[q]]++] = static_cast<std::uint32_t>(q);
  for (std::size_t parity = 0; parity < 2; ++parity) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if (threads > 1)
    for (std::size_t s = parity; s < slabs; s += 2) kernel(order.data() + start[s], start[s + 1] - start[s]);
  }
}

}  // namespace detail

// Steps 3-5: nodal mass (eq. 3.11), momentum for the velocity re-mapped from particles
// (eq. 3.16) and internal force f_i = -sum_p V_p (sigma_p - q_p I) . G_ip (eq. 3.9 /
// 3.30 / 4.5). `reference_volume`: integrate over V0 (geometrically linear, small
// strain) instead of the current V.
template <int Dim>
void p2g(const Particles<Dim>& p, const Stencil<Dim>& st, bool reference_volume, Grid<Dim>& g, int threads = 1) {
  if constexpr (Dim == 1) {
    for (std::size_t i = 0; i < g.storage; ++i) {
      g.mass[i] = 0.0;
      g.momentum[0][i] = g.force[0][i] = 0.0;
    }
  } else {
    clear_active(g, threads);  // what the last step wrote
    mark_active_lines(g, st, threads);
  }
  const std::vector<double>& vol = reference_volume ? p.volume0 : p.volume;
  const bool smooth = st.smoothed();
  if (smooth)
    for (auto& t : g.smooth_stress)
      if (t.size() != g.storage) t.assign(g.storage, 0.0);
  auto kernel = [&](const std::uint32_t* list, std::size_t count) {
    if (smooth) switch (st.width) {  // DDMP: the hat's 2^d nodes, sub-points wider
        case 4: return detail::p2g_kernel<Dim, 4, true>(p, st, vol, g, list, count);
        case 8: return detail::p2g_kernel<Dim, 8, true>(p, st, vol, g, list, count);
        default: return detail::p2g_kernel<Dim, 0, true>(p, st, vol, g, list, count);
      }
    switch (st.width) {
      case 2: return detail::p2g_kernel<Dim, 2, false>(p, st, vol, g, list, count);
      case 4: return detail::p2g_kernel<Dim, 4, false>(p, st, vol, g, list, count);
      case 5: return detail::p2g_kernel<Dim, 5, false>(p, st, vol, g, list, count);
      case 8: return detail::p2g_kernel<Dim, 8, false>(p, st, vol, g, list, count);
      case 16: return detail::p2g_kernel<Dim, 16, false>(p, st, vol, g, list, count);
      default: return detail::p2g_kernel<Dim, 0, false>(p, st, vol, g, list, count);
    }
  };
  if constexpr (Dim == 1) {
    kernel(nullptr, p.size());
  } else {
    detail::scatter_in_slabs(g, st, p.size(), threads, kernel);
  }
  if (smooth) shape::add_smoothed_force(g, st, threads);  // eq. 7.2's smoothed part
}

// Steps 9-10 and 7: particle velocity by the nodal velocity change (eq. 3.13), position
// when particles move, and the velocity gradient with the scheme's gradient
// (eq. 4.10 / 6.3). Both use v^{n+1/2} = (v^L + v^n)/2 (eqs. 3.14, 4.10: energy error
// second order) when `midpoint`, else v^L (symplectic: stable where forces depend on
// positions, as for the isothermal gas whose V_p p_p is constant). Returns the sum of
// the new velocities and positions, for a cheap finiteness check.
template <int Dim>
double g2p(Grid<Dim>& g, const Stencil<Dim>& st, double dt, bool move, bool midpoint,
           Particles<Dim>& p, int threads = 1) {
  const VelocityWeights vw = midpoint_weights(midpoint);
  const double wl = vw.L, wn = vw.n;
  const bool own = !g.gradient_velocity[0].empty();
  auto run = [&]<bool Smooth, bool Own>() {
    switch (st.width) {
      case 2: return detail::g2p_kernel<Dim, 2, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
      case 4: return detail::g2p_kernel<Dim, 4, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
      case 5: return detail::g2p_kernel<Dim, 5, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
      case 8: return detail::g2p_kernel<Dim, 8, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
      case 16: return detail::g2p_kernel<Dim, 16, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
      default: return detail::g2p_kernel<Dim, 0, Smooth, Own>(g, st, dt, move, wl, wn, p, threads);
    }
  };
  if (st.smoothed()) {  // eq. 7.2's smoothed gradient on the nodes, of the velocities the gradient reads
    std::array<const double*, Dim> vl, vn;
    for (int a = 0; a < Dim; ++a) {
      vl[a] = (own ? g.gradient_velocity : g.velocity_L)[a].data();
      vn[a] = g.velocity[a].data();
    }
    if (own) shape::smoothed_gradient(st, vl, g, threads);
    else shape::smoothed_gradient(st, vl, vn, vw, g, threads);
    return own ? run.template operator()<true, true>() : run.template operator()<true, false>();
  }
  return own ? run.template operator()<false, true>() : run.template operator()<false, false>();
}

}  // namespace mpmx::mpm
