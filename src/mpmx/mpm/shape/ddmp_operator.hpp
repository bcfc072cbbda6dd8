#pragma once
// DDMP's smoothed gradient as an operator on the grid. Eq. 7.2's smoothed part of node
// i's gradient at x is sum_j S_j(x) K^d_ji, with K^d_ji = D_{j_d i_d} prod_{a != d}
// (M / V)_{j_a i_a} (the 1-D nodal-gradient operator along d, eq. 3.31, and the smoothed
// shape along the other axes; ddmp.hpp). So the internal force's smoothed part is
//   f_i -= sum_d sum_j T^d_j K^d_ji,   T^d_j = sum_p V_p sigma_p[:, d] (1 - alpha_p) S_jp,
// and the velocity gradient's is sum_j (1 - alpha_p) S_jp H_j, H^{ab}_j = sum_i K^b_ji v_ai:
// the points scatter and gather on the hat's 2^d nodes and K is applied once per node
// rather than once per point (4^d entries per point otherwise). theory.md, "DDMP on the
// grid".
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {

// Fills st.smooth_marks: the nodes a point's box holds and those within one node of
// them (the reach); `scratch` is scratch.
template <int Dim>
void mark_smoothing_nodes(const Grid<Dim>& g, Stencil<Dim>& st, std::vector<std::uint8_t>& scratch, int threads = 1);

// The two below visit the grid's active lines (active_lines.hpp), which p2g marks.

// f_i -= sum_d sum_j T^d_j K^d_ji at the reach, then T back to zero.
template <int Dim>
void add_smoothed_force(Grid<Dim>& g, const Stencil<Dim>& st, int threads);

// H^{ab}_j = sum_i K^b_ji v_ai at the stencil's nodes.
template <int Dim>
void smoothed_gradient(const Stencil<Dim>& st, const std::type_identity_t<std::array<const double*, Dim>>& v,
                       Grid<Dim>& g, int threads);
// The same of v = w.L vL + w.n vn.
template <int Dim>
void smoothed_gradient(const Stencil<Dim>& st, const std::type_identity_t<std::array<const double*, Dim>>& vL,
                       const std::type_identity_t<std::array<const double*, Dim>>& vn, VelocityWeights w,
                       Grid<Dim>& g, int threads);

// The gradient written out in full, sharp plus smoothed, on each point's box widened by
// one node on every side (unfactored: R empty). For tests and as the reference form.
template <int Dim>
Stencil<Dim> expanded(const Stencil<Dim>& st, const Grid<Dim>& g);

}  // namespace mpmx::mpm::shape
