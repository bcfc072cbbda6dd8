#pragma once
// What a pair-force evaluation sums over its pairs, whichever engine runs it: the energy
// and the pair virial W_ab = sum over pairs of r_ab,a r_ab,b f_ab/r (eq. 2.25 first line,
// potential part, times the volume), both in eV.
#include <array>

namespace mpmx::particles {

using Sym6 = std::array<double, 6>;  // xx, yy, zz, xy, xz, yz

struct ForceSums {
  double energy = 0;  // eV
  Sym6 virial{};      // eV
};

}  // namespace mpmx::particles
