#pragma once
// The original-MPM transfers in 1-D fused with the hat evaluation (eqs. 3.9-3.16):
// no stencil is stored, and consecutive particles of one cell accumulate in registers
// before touching the nodes. Same arithmetic as shape/linear + transfer, faster.
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {

// Cell and fraction of each particle, kept from p2g for g2p (positions do not change
// in between).
struct LinearCells {
  std::vector<int> cell;
  std::vector<double> frac;
  std::vector<double> grad;  // 1/dx inside the grid, 0 past its ends
  // Per-cell sums of m, m f, m v, m v f and V sigma G ([field][cell]).
  std::vector<double> sums;
  // Per-cell node values for g2p: dv at the left node and its jump, same for the
  // velocity that moves the particle.
  std::vector<double> d0, dd, g0, dg;
};

void p2g_linear(const Grid<1>& g, const Particles<1>& p, bool reference_volume, LinearCells& lc,
                Grid<1>& out);
double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                  Particles<1>& p);

}  // namespace mpmx::mpm::shape
