#pragma once
// The original-MPM and DDMP transfers in 1-D fused with the hat evaluation (eqs. 3.9-3.16,
// 3.31, 6.1-6.3): no stencil is stored, and consecutive particles of one cell accumulate
// in registers before touching the nodes. Same algorithm as shape/{linear,ddmp} +
// transfer; the sums are regrouped per cell, so results agree to round-off. Each call runs
// the best vector path of the machine (core/isa.hpp).
#include <string>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {

// Cell and fraction of each particle, kept from p2g for g2p (positions do not change
// in between).
struct LinearCells {
  std::vector<int> cell;
  std::vector<double> frac;
  std::vector<double> grad;  // 1/dx inside the grid, 0 past its ends
  // Per-cell sums ([field][cell + 2], two zero cells padding each end): m, m f, m v, m v f, then
  // the force fields (V sigma, or V sigma G, for MPM; V sigma times the DDMP weights below).
  std::vector<double> sums;
  std::vector<double> val;  // scratch of the DDMP passes
  // Per-cell node values for g2p: the velocity change at the cell's left node and its
  // jump to the right node; the same for the velocity that moves the particle.
  std::vector<double> dv_left, dv_jump, vmove_left, vmove_jump;
  std::vector<double> at_particle;  // those four at each particle ([table][particle])
  bool ordered = false;    // particles in cell order at the last p2g (as its sums found;
                           // the next p2g takes it as given and its sums test it again)
  bool inside = false;     // and all between the grid's ends (grad = 1/dx for all)
  // DDMP (eq. 3.31): per particle the weights of its gradient (ddmp_w[k * n + q]): at the
  // particle alpha, (1-alpha)(1-f), (1-alpha) f; with sub-points their averages over
  // the sub-points in the particle's cell (see subpoint_weights), so that
  // Gbar_i = sum alpha dS_i/dx + sum_j D_ji Q_j.
  std::vector<double> ddmp_w;
  std::vector<double> ddmp_w_next;  // weights in the neighbouring cells ([k * n + q], k = 0..3)
  std::vector<int> mixed;  // particles with sub-points in a neighbouring cell
  std::vector<int> stray;  // particles with sub-points more than a cell from theirs
  // The smoothing operator's rows by node storage index: D_{j,j-1}, D_{j,j}, D_{j,j+1}.
  std::vector<double> ddmp_d_left, ddmp_d_centre, ddmp_d_right;
  std::vector<double> scratch_sums, scratch_dv;  // per-cell alpha sums / padded dv; Q / D v
};

// What step() does after g2p for a 1-D linear elastic solid without artificial viscosity
// (stress work with the stress of the forces, eq. 4.11, over V0 for small strain; V and a
// tracked domain length *= 1 + dt L; eps += dt L; sigma = E eps), for a g2p that can do it
// in its own pass: `done` says whether it did, and `stress_work` gains dt * work.
struct ElasticUpdate {
  bool small_strain = false;
  double youngs_modulus = 0.0;
  double stress_work = 0.0;
  bool done = false;
};

// `no_viscous_pressure`: every q_p is zero (no artificial viscosity).
void p2g_linear(const Grid<1>& g, const Particles<1>& p, bool reference_volume,
                bool no_viscous_pressure, LinearCells& lc, Grid<1>& out);
// `update` (may be null): the elastic update, done in the same pass (always, for mpm).
double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                  Particles<1>& p, ElasticUpdate* update = nullptr);

// DDMP (subpoints == 0) and DDMP with sub-points (eqs. 4.5-4.6, 6.1-6.3): the hat for S
// at the particle, the modified gradient of eq. 3.31 at the particle or averaged over
// `subpoints` points spread evenly in the particle domain.
void p2g_ddmp(const Grid<1>& g, const Particles<1>& p, bool reference_volume, int subpoints,
              LinearCells& lc, Grid<1>& out);
// `update` (may be null): the elastic update to do in the same pass where it can.
double g2p_ddmp(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                int subpoints, Particles<1>& p, ElasticUpdate* update = nullptr);

// The path these kernels' dispatch takes now, as the kernels themselves report it
// (tests; MPMX_ISA and isa_use in core/isa.hpp choose it).
std::string isa_dispatched();

}  // namespace mpmx::mpm::shape
