#pragma once
// Pieces shared by the fused 1-D kernels (linear_fused.cpp) and the DDMP sub-point
// weights (subpoint_weights.cpp), on every vector path; not part of the library's interface.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape::fused {

// Cell (clamped to the grid, eq. 3.9: the flat continuation past the ends) and fraction
// of a point at xi in cell units, as locate(clamp_to_grid(xi)) but free of int round
// trips so that loops over it vectorise. xc >= 0: truncation is floor. A NaN lands in
// cell 0 (as the vector kernels' max does) rather than in an undefined conversion, so the
// cell is an index into the grid whatever the position; callers report a NaN apart.
struct Cell {
  double c, f;
};
inline Cell cell_of(double xi, double top) {
  const double xc = std::min(xi > 0.0 ? xi : 0.0, top);
  const double cc = std::min(static_cast<double>(static_cast<int>(xc)), top - 1.0);
  return {cc, xc - cc};
}

// A sub-point's cell and weights (eq. 3.31 at xi): as add_ddmp_gradient.
struct SubWeights {
  int c;
  double a, b0, b1;  // alpha, (1 - alpha)(1 - f), (1 - alpha) f
};
inline SubWeights sub_weights(double xi, double top) {
  const Cell cf = cell_of(xi, top);
  const double a = ddmp_alpha(cf.f), b = 1.0 - a;
  return {static_cast<int>(cf.c), a, b * (1.0 - cf.f), b * cf.f};
}

// Sub-point s of a particle at xi with half width h and spacing step (cell units), as
// evaluate_ddmp_subpoints places them.
inline double sub_h(double len, double inv, int n_sub) {
  return 0.5 * len * inv * (1.0 - 1.0 / n_sub);
}
inline double sub_step(double h, int n_sub) { return n_sub > 1 ? 2.0 * h / (n_sub - 1) : 0.0; }

// DDMP weights of every particle averaged over its n_sub sub-points (eqs. 3.31, 6.1-6.3),
// summed per cell of the sub-points relative to the particle's cell c. In plain DDMP's
// layout, W[k * n + q] for k = 0..2 = <alpha> in cell c and <(1-alpha) S_j> at nodes c and
// c+1 (S_j the hat of the sub-point's cell); Wx[k * n + q] for k = 0..3 = <alpha> in cells
// c-1, c+1 and <(1-alpha) S_j> at nodes c-1, c+2 (zero for a particle that keeps its
// sub-points in c). `mixed` lists, in order, the particles with sub-points outside c;
// `stray` those with one more than a cell away (handled apart). subpoint_weights.cpp: it
// runs the vector path the caller runs (dispatch picks the same for both).
void subpoint_weights(std::size_t n, const double* __restrict x, const double* __restrict len,
                      const int* __restrict cell, double x0, double inv, double top, int ns,
                      double* __restrict W, double* __restrict Wx, std::vector<int>& mixed,
                      std::vector<int>& stray);

// The Highway target the kernels' dispatch takes now (linear_fused.cpp).
int64_t dispatched_target();

}  // namespace mpmx::mpm::shape::fused
