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
  // M_{j,i} / V_j for i = j-1, j, j+1, M_ji = int S_j S_i dx: the smoothed shape
  // sum_j S_j(x) M_ji / V_j that carries eq. 7.2's smoothed gradient across the other
  // axes of a tensor-product grid (2-D, 3-D).
  std::vector<double> bm, b0, bp;
  // The same rows interleaved for the grid operator: row[3 s + 1 + o] is the entry of
  // node s for node s + o, o = -1, 0, 1.
  std::vector<double> d3, b3;
  // Along one axis of `cells` cells of width dx.
  DdmpTable(int cells, double dx);
  explicit DdmpTable(const Grid<1>& g) : DdmpTable(g.cells[0], g.dx[0]) {}
};

// Adds w * Gbar_i(xi) for i = c-1 .. c+2 into out[base + (c - 1 - first) ...], i.e.
// into the entries of the nodes starting at grid index `first`.
void add_ddmp_gradient(const Grid<1>& g, const DdmpTable& t, double xi, double w, int first,
                       double* out);

}  // namespace mpmx::mpm::shape
