#pragma once
// DPD pair forces (seed 004 eqs. 2.2-2.5; Groot and Warren 1997). The conservative
// force of the pair potential, F^C_ij = -U'(r) e_ij (eq. 2.3), and, for the
// velocity-Verlet integrator (isothermal DPD, LAMMPS `pair dpd` + `fix nve`), the
// dissipative and random forces
//   F^D_ij = -gamma w^D(r) (e_ij . v_ij) e_ij,              (eq. 2.4)
//   F^R_ij = sigma w^R(r) theta_ij e_ij / sqrt(dt),           (eq. 2.5)
//   w^R = 1 - r/rc_d, w^D = (w^R)^2, sigma^2 = 2 gamma k_B T,
// theta_ij a standard normal number per pair and step (pair_random.hpp).
//
// Every pair of the half list is evaluated once, tile by tile (the list's tiles: runs of
// consecutive particles, threads over tiles), its force added to its particle's and
// taken from its partner's entry in the tile's own array; every particle then adds its
// shares from all tiles in tile order (threads over particles): results are bitwise the
// same for any thread count. Energy and virial are summed per particle, then over
// particles in index order.
#include <cstdint>
#include <vector>

#include "mpmx/dpd/pair_list.hpp"
#include "mpmx/dpd/particles.hpp"
#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/particles/force_sums.hpp"

namespace mpmx::dpd {

// The dissipative and random pair forces of one force evaluation.
struct StochasticForces {
  double gamma = 0;        // amu/ps
  double temperature = 0;  // K
  double cutoff = 1;       // rc_d, Angstrom
  double dt = 1;           // ps (the random force scales as 1/sqrt(dt))
  std::uint64_t seed = 0;
  std::int64_t step = 0;   // the random numbers' counter
};

struct ForceBuffers {
  std::vector<double> tile_force;  // 3 per entry of each tile, eV/Angstrom
  std::vector<double> energy;      // per particle (each pair to its particle i)
  std::vector<double> virial;      // 6 per particle
};

// Forces on every particle into p.fx, p.fy, p.fz (eV/Angstrom); with `tally`, returns
// the conservative energy (eV) and the virial W_ab = sum over pairs of r_a F_b (eV) of
// the forces computed (zeros without). `stochastic` null: conservative forces only. The
// list's positions must be current (PairList::update_positions).
// `no_pair` (null: none): particles flagged there do not interact with each other (the
// continuum points of a concurrent run); their pairs with the others count as usual.
particles::ForceSums compute_pair_forces(const PairPotential& pot, const PairList& list, Particles& p,
                                  const StochasticForces* stochastic, ForceBuffers& buf, int threads,
                                  bool tally = true, const std::uint8_t* no_pair = nullptr);

}  // namespace mpmx::dpd
