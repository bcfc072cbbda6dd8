#pragma once
// The stochastic half of the Shardlow splitting (Shardlow 2003; Lisal, Brennan and
// Bonet Avalos, J. Chem. Phys. 135, 204105 (2011): the scheme of LAMMPS's DPD-REACT
// `fix shardlow`). For every pair in turn, the dissipative and random forces of seed
// 004 eqs. 2.4-2.5 act over dt on the pair's own velocities: an explicit half step,
// then an implicit half step with the same random number,
//   R = sigma_ij w^R sqrt(dt) theta_ij / 2,   G = gamma w^D dt / 2,   g = e_ij . v_ij,
//   A = R - G g;                            v_i += A e_ij/m_i,  v_j -= A e_ij/m_j,
//   B = (R - G g') / (1 + G (1/m_i + 1/m_j)); v_i += B e_ij/m_i,  v_j -= B e_ij/m_j,
// with w^R = 1 - r/rc_d, w^D = (w^R)^2, g' = g + A (1/m_i + 1/m_j); together the impulse
// P = A + B = 2 (R - G g) / (1 + G (1/m_i + 1/m_j)), applied once. Momentum is
// conserved pair by pair.
//
// DPDE (energy-conserving DPD): sigma_ij^2 = 2 gamma k_B T_ij with
// 1/T_ij = (1/T_i + 1/T_j)/2 and T_i = u_i / C_v taken at the start of the sweep (as
// LAMMPS's fix shardlow takes dpdTheta, updated once per step); the pair's kinetic
// energy change,
// dK = P (g + g')/2 for the impulse P = A + B, is taken from the internal energies,
// u_i -= dK/2, u_j -= dK/2, so kinetic + potential + internal energy is conserved by
// each pair update. Isothermal DPD: T_ij = T, no internal energies.
//
// Order: the pairs' update is sequential by nature (a pair sees its predecessors'
// velocities). The pairs are taken slab by slab in five phases (PairList: slabs of one
// phase share no particle), so the slabs of a phase run on threads without changing
// any number: the result is the same for any thread count (as LAMMPS's SSA does with
// its spatial phases).
// Rigid particles count as infinitely heavy (1/m = 0): they are not moved.
#include <cstdint>
#include <vector>

#include "mpmx/dpd/pair_list.hpp"
#include "mpmx/dpd/particles.hpp"

namespace mpmx::dpd {

struct SweepParams {
  double gamma = 0;          // amu/ps
  double cutoff = 1;         // rc_d, Angstrom
  double dt = 0;             // ps
  bool energy_conserving = false;
  double temperature = 0;    // K (isothermal)
  double heat_capacity = 0;  // C_v per particle, eV/K (DPDE)
  std::uint64_t seed = 0;
  std::int64_t step = 0;
};

// Per-particle inverse masses (0 for rigid particles) and inverse temperatures of a sweep.
struct SweepWork {
  std::vector<double> inv_mass, inv_temperature;
};

// One stochastic step over every pair of the list (positions as in list.nb.xyz).
void shardlow_sweep(const PairList& list, Particles& p, const SweepParams& sp, SweepWork& work, int threads);

}  // namespace mpmx::dpd
