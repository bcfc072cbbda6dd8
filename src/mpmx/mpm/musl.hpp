#pragma once
// MUSL (Sulsky, Zhou and Schreyer 1995; the peer's default): after g2p has moved the
// points with v^L and updated their velocities, their new momenta are mapped back to the
// nodes, v_i = sum_p m_p v_p S_ip / m_i with the faces' conditions at t^{n+1}, and the
// velocity gradient is read from these (through the small-mass distribution's adjoint
// where it is on) rather than from v^L or v^{n+1/2} (`update_velocity = "musl"`). The extra map smooths the gradient the stress sees,
// which is what keeps colliding bodies' energy (docs/validation.md, N3).
#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "mpmx/mpm/active_lines.hpp"
#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/mass_distribution.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"
#include "mpmx/mpm/transfer.hpp"

namespace mpmx::mpm {

template <int Dim>
void musl_gradient(const Stencil<Dim>& st, const Boundaries& bc, double t, Grid<Dim>& g, Particles<Dim>& p,
                   const SmallMassMaps* small_mass, std::type_identity_t<std::array<std::vector<double>, Dim>>& v,
                   int threads) {
  const int w = st.width;
  const std::size_t n = p.size();
  // Node i's velocity from the points' momenta, or its face's at t where one holds it
  // (a piston's where the material there would fall behind it).
  auto node_velocity = [&](std::size_t i, const std::array<int, Dim>& idx) {
    const double m = g.mass[i];
    for (int a = 0; a < Dim; ++a) {
      double vi = m > 0.0 ? v[a][i] / m : 0.0;
      for (int f = 0; f < 2 * Dim; ++f) {
        const int axis = f / 2;
        const bool on = (f % 2 == 0) ? idx[axis] == 0 : idx[axis] == g.cells[axis];
        if (on && bc.face[f].holds(a, f, vi, t)) {
          vi = bc.face[f].velocity(t, a, f);
          break;
        }
      }
      v[a][i] = vi;
    }
  };
  auto scatter = [&](const std::uint32_t* list, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t q = list ? list[k] : k;
      for (int e = 0; e < w; ++e) {
        const std::size_t at = q * w + e;
        const double mS = p.mass[q] * st.S[at];
        for (int a = 0; a < Dim; ++a) v[a][st.node[at]] += mS * p.v[a][q];
      }
    }
  };
  if constexpr (Dim == 1) {
    for (int a = 0; a < Dim; ++a) v[a].assign(g.storage, 0.0);
    scatter(nullptr, n);
    g.for_each_node(node_velocity);
  } else {
    // On the grid's active lines (active_lines.hpp, where the stencils' nodes lie), the
    // momenta scattered in slabs as p2g does (the same sums for any thread count), the
    // velocities over the span (nodes the points left get v = 0).
    for (auto& c : v)
      if (c.size() != g.storage) c.assign(g.storage, 0.0);
    for_each_range(g, g.active_lo, g.active_hi, threads, [&](std::size_t, std::size_t i0, int lo, int hi) {
      for (int a = 0; a < Dim; ++a)
        std::fill(&v[a][i0 + static_cast<std::size_t>(lo)], &v[a][i0 + static_cast<std::size_t>(hi)] + 1, 0.0);
    });
    detail::scatter_in_slabs(g, st, n, threads, scatter);
    for_each_range(g, g.span_lo, g.span_hi, threads, [&](std::size_t l, std::size_t i0, int lo, int hi) {
      auto idx = g.line_first(l);
      for (int x = lo; x <= hi; ++x) {
        idx[0] = x;
        node_velocity(i0 + static_cast<std::size_t>(x), idx);
      }
    });
  }
  if (small_mass)  // the gradient reads the adjoint of the force distribution (eq. 7.7)
    adjoint_velocity<Dim>(*small_mass, v, threads);
  const bool smooth = st.smoothed();
  if (smooth) {  // DDMP: eq. 7.2's smoothed gradient on the nodes
    std::array<const double*, Dim> vv;
    for (int a = 0; a < Dim; ++a) vv[a] = v[a].data();
    shape::smoothed_gradient(st, vv, g, threads);
  }
  auto gradients = [&]<bool Smooth>() {
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t q = 0; q < n; ++q) {
      double L[Dim][Dim] = {};
      for (int k = 0; k < w; ++k) {
        const std::size_t e = q * w + k;
        const int i = st.node[e];
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) {
            L[a][b] += v[a][i] * st.G[b][e];
            if constexpr (Smooth) L[a][b] += st.R[e] * g.smooth_gradient[a * Dim + b][i];
          }
      }
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.grad_v[a * Dim + b][q] = L[a][b];
    }
  };
  if (smooth) gradients.template operator()<true>();
  else gradients.template operator()<false>();
}

}  // namespace mpmx::mpm
