#pragma once
// The small-mass distribution of DDMP (dissertation eqs. 7.4-7.7). DDMP's gradient
// reaches one cell further than the shape functions, so nodes without mass receive
// internal force and their (zero) velocity enters the velocity gradient; nodes of tiny
// mass get huge accelerations. Forces (eq. 7.6): the force of a node l without mass goes
// to the nodes sharing a cell with it in proportion to sqrt(m) (C0, eq. 7.4); then that
// of a node with 0 < m_l <= m_eps is shared the same way among l and its cell neighbours
// (C1, eq. 7.5). Each stage is a linear map A whose columns sum to one, so the total
// force is kept exactly. Velocities (eq. 7.7, whose indices the source garbles): the
// velocities the velocity gradient reads are the transposed map, v~ = A0^T A1^T v,
// so such a node takes the sqrt(m)-weighted mean velocity of its neighbourhood. The
// pair is adjoint: the power of the distributed forces on v equals that of the
// original forces on v~, sum f.v~ = sum (A f).v, which keeps the energy balance
// (eq. 4.11) of the step; momentum is kept because the particle update reads v itself.
#include <array>
#include <cstdint>
#include <vector>

#include "mpmx/mpm/grid.hpp"

namespace mpmx::mpm {

// One stage's map: for each source node, its neighbours and their weights.
struct SmallMassMap {
  std::vector<std::uint32_t> source, start, node;
  std::vector<double> weight;
  void clear() {
    source.clear(), node.clear(), weight.clear();
    start.assign(1, 0);
  }
};
struct SmallMassMaps {
  SmallMassMap c0, c1;  // eqs. 7.4 and 7.5, built from this step's nodal masses
  std::vector<SmallMassMap> parts;  // scratch: the maps of runs of node lines, built apart
};

// Builds the maps from the nodal masses, then forces f <- A1 A0 f. Threads over runs of
// node lines, whose maps are joined in line order: the same maps for any count.
template <int Dim>
void distribute_small_mass_forces(Grid<Dim>& g, double m_eps, SmallMassMaps& maps, int threads = 1);

// After the solve: Grid::gradient_velocity <- A0^T A1^T (w.L velocity_L + w.n velocity),
// the velocities the gradient reads (the adjoint is linear: one set, not one per field).
template <int Dim>
void gradient_velocities(Grid<Dim>& g, const SmallMassMaps& maps, VelocityWeights w, int threads = 1);

// v <- A0^T A1^T v for every nodal velocity component (what a gradient reads).
template <int Dim>
void adjoint_velocity(const SmallMassMaps& maps, std::array<std::vector<double>, Dim>& v, int threads = 1);

}  // namespace mpmx::mpm
