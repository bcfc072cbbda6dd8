#pragma once
// Particle-to-grid and grid-to-particle transfers over a precomputed stencil
// (dissertation sec. 3.1, steps 3-10). One loop shape serves every scheme.
#include <cstddef>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm {

// Steps 3-5: nodal mass (eq. 3.11), velocity re-mapped from particles (eq. 3.16) and
// internal force f_i = -sum_p V_p (sigma_p - q_p I) . G_ip (eq. 3.9 / 3.30 / 4.5).
// `reference_volume`: integrate over V0 (geometrically linear, small strain) instead of V.
template <int Dim>
void p2g(const Particles<Dim>& p, const Stencil<Dim>& st, bool reference_volume, Grid<Dim>& g) {
  const std::vector<double>& vol = reference_volume ? p.volume0 : p.volume;
  std::fill(g.mass.begin(), g.mass.end(), 0.0);
  for (int d = 0; d < Dim; ++d) {
    std::fill(g.momentum[d].begin(), g.momentum[d].end(), 0.0);
    std::fill(g.force[d].begin(), g.force[d].end(), 0.0);
  }
  const int W = st.width;
  const std::size_t n = p.size();
  for (std::size_t q = 0; q < n; ++q) {
    const double m = p.mass[q], V = vol[q], qv = p.viscous_pressure[q];
    double mv[Dim], sig[Dim][Dim];
    for (int a = 0; a < Dim; ++a) {
      mv[a] = m * p.v[a][q];
      for (int b = 0; b < Dim; ++b) sig[a][b] = V * (p.stress[a * Dim + b][q] - (a == b ? qv : 0.0));
    }
    const std::size_t e0 = q * W;
    for (int k = 0; k < W; ++k) {
      const std::size_t e = e0 + k;
      const int i = st.node[e];
      const double S = st.S[e];
      g.mass[i] += m * S;
      for (int a = 0; a < Dim; ++a) {
        g.momentum[a][i] += mv[a] * S;
        double f = 0.0;
        for (int b = 0; b < Dim; ++b) f += sig[a][b] * st.G[b][e];
        g.force[a][i] -= f;
      }
    }
  }
}

// Step 9-10 and 7: particle velocity by the nodal velocity change (eq. 3.13), position
// when particles move, and the velocity gradient with the scheme's gradient
// (eq. 4.10 / 6.3). Both use v^{n+1/2} = (v^L + v^n)/2 (eqs. 3.14, 4.10: energy error
// second order) when `midpoint`, else v^L (symplectic: stable where forces depend on
// positions, as for the isothermal gas whose V_p p_p is constant).
template <int Dim>
void g2p(const Grid<Dim>& g, const Stencil<Dim>& st, double dt, bool move, bool midpoint,
         Particles<Dim>& p) {
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const int W = st.width;
  const std::size_t n = p.size();
  for (std::size_t q = 0; q < n; ++q) {
    double dv[Dim] = {}, vbar[Dim] = {}, L[Dim][Dim] = {};
    const std::size_t e0 = q * W;
    for (int k = 0; k < W; ++k) {
      const std::size_t e = e0 + k;
      const int i = st.node[e];
      const double S = st.S[e];
      for (int a = 0; a < Dim; ++a) {
        const double vl = g.velocity_L[a][i], vn = g.velocity[a][i];
        const double vg = wl * vl + wn * vn;
        dv[a] += (vl - vn) * S;
        vbar[a] += vg * S;
        for (int b = 0; b < Dim; ++b) L[a][b] += vg * st.G[b][e];
      }
    }
    for (int a = 0; a < Dim; ++a) {
      p.v[a][q] += dv[a];
      if (move) p.x[a][q] += dt * vbar[a];
      for (int b = 0; b < Dim; ++b) p.grad_v[a * Dim + b][q] = L[a][b];
    }
  }
}

}  // namespace mpmx::mpm
