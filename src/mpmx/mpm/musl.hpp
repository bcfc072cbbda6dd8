#pragma once
// MUSL (Sulsky, Zhou and Schreyer 1995; the peer's default): after g2p has moved the
// points with v^L and updated their velocities, their new momenta are mapped back to the
// nodes, v_i = sum_p m_p v_p S_ip / m_i with the faces' conditions at t^{n+1}, and the
// velocity gradient is read from these (through the small-mass distribution's adjoint
// where it is on) rather than from v^L or v^{n+1/2} (`update_velocity = "musl"`). The extra map smooths the gradient the stress sees,
// which is what keeps colliding bodies' energy (docs/validation.md, N3).
#include <array>
#include <type_traits>
#include <vector>

#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/mass_distribution.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"

namespace mpmx::mpm {

template <int Dim>
void musl_gradient(const Stencil<Dim>& st, const Boundaries& bc, double t, Grid<Dim>& g, Particles<Dim>& p,
                   const SmallMassMaps* small_mass, std::type_identity_t<std::array<std::vector<double>, Dim>>& v,
                   int threads) {
  const int w = st.width;
  const std::size_t n = p.size();
  for (int a = 0; a < Dim; ++a) v[a].assign(g.storage, 0.0);
  for (std::size_t q = 0; q < n; ++q) {  // one thread: every node sums in point order
    for (int k = 0; k < w; ++k) {
      const std::size_t e = q * w + k;
      const double mS = p.mass[q] * st.S[e];
      for (int a = 0; a < Dim; ++a) v[a][st.node[e]] += mS * p.v[a][q];
    }
  }
  g.for_each_node([&](std::size_t i, const std::array<int, Dim>& idx) {
    const double m = g.mass[i];
    for (int a = 0; a < Dim; ++a) {
      double vi = m > 0.0 ? v[a][i] / m : 0.0;
      for (int f = 0; f < 2 * Dim; ++f) {
        const int axis = f / 2;
        const bool on = (f % 2 == 0) ? idx[axis] == 0 : idx[axis] == g.cells[axis];
        if (on && bc.face[f].holds(a, axis)) {
          vi = bc.face[f].velocity(t, a);
          break;
        }
      }
      v[a][i] = vi;
    }
  });
  if (small_mass)  // the gradient reads the adjoint of the force distribution (eq. 7.7)
    for (int a = 0; a < Dim; ++a) adjoint_velocity(*small_mass, v[a], threads);
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
