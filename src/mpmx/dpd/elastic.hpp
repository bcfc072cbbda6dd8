#pragma once
// The elastic constants of a static fcc lattice of mesoparticles bound by a pair
// potential (the Born lattice sums): the constants of "the DPD model" that the
// continuum side of a concurrent DPD/MPM run takes (seed 004 sec. 4.2). Per particle,
// with B(r) = (U''(r) - U'(r)/r) / r^2 and Omega = a^3 / 4 the volume per particle,
//   C_abcd = 1/(2 Omega) sum_j B(r_j) r_a r_b r_c r_d,
// so C12 = C44 (the Cauchy relation of central forces). The prestress terms of a lattice
// not at zero pressure are left out.
#include "mpmx/dpd/potential/registry.hpp"

namespace mpmx::dpd {

struct LatticeConstants {
  double c11 = 0, c12 = 0, c44 = 0;  // eV / Angstrom^3
  double pressure = 0;               // of the static lattice, eV / Angstrom^3
};

LatticeConstants fcc_born_constants(const PairPotential& pot, double lattice_constant);

}  // namespace mpmx::dpd
