#pragma once
// Dual domain material point method in 1-D: the modified gradient of eq. 3.31,
//   Gbar_i(x) = alpha(x) dS_i/dx + (1 - alpha(x)) sum_j S_j(x) D_ji,
//   D_ji = (1/V_j) int S_j dS_i/dx dV,
// with alpha of eq. 3.27. D is the nodal-gradient operator of the grid (central
// differences inside, one-sided at the ends), precomputed once per grid.
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {

struct DdmpTable {
  // D_{j,j-1}, D_{j,j}, D_{j,j+1} for node j (storage index incl. ghosts; zero on ghosts).
  std::vector<double> dm, d0, dp;
  explicit DdmpTable(const Grid<1>& g);
};

// Adds w * Gbar_i(xi) for i = c-1 .. c+2 into out[base + (c - 1 - first) ...], i.e.
// into the entries of the nodes starting at grid index `first`.
void add_ddmp_gradient(const Grid<1>& g, const DdmpTable& t, double xi, double w, int first,
                       double* out);

// DDMP: hat shape functions, modified gradient at the particle (eq. 3.31).
void evaluate_ddmp(const Grid<1>& g, const DdmpTable& t, const Particles<1>& p, Stencil<1>& st);

// DDMP with sub-points (eqs. 4.5-4.6, 6.1-6.3): n sub-points placed evenly in the
// particle domain [x - l/2, x + l/2]; the gradient is their volume-weighted average
// (equal volumes V_p / n); the shape function stays the hat at the particle.
void evaluate_ddmp_subpoints(const Grid<1>& g, const DdmpTable& t, const Particles<1>& p,
                             int n, Stencil<1>& st);

}  // namespace mpmx::mpm::shape
