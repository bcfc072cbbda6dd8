// ctest-label: validation
// M1 (fig. 7.2 with Cu): energy per atom of perfect fcc Cu against the lattice constant,
// Cu_mishin1.eam.alloy: minimum at 3.615 +- 0.002 Angstrom, -3.54 +- 0.005 eV/atom.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

using namespace mpmx::md;

TEST(M1, CohesiveEnergyCurveOfCopper) {
  EamSpec spec;
  spec.file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";
  Potential pot(spec);
  auto energy = [&](double a) {
    System s(fcc(4, 4, 4, a), pot);
    return s.potential_energy() / s.atoms().size();
  };
  // Golden-section search for the minimum on [3.5, 3.7].
  double lo = 3.5, hi = 3.7;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
  double fc = energy(c), fd = energy(d);
  for (int it = 0; it < 40; ++it) {
    if (fc < fd) hi = d, d = c, fd = fc, c = hi - g * (hi - lo), fc = energy(c);
    else lo = c, c = d, fc = fd, d = lo + g * (hi - lo), fd = energy(d);
  }
  const double a0 = 0.5 * (lo + hi), e0 = energy(a0);
  RecordProperty("a0", std::to_string(a0));
  RecordProperty("E0", std::to_string(e0));
  std::printf("M1: a0 = %.5f Angstrom, E0 = %.5f eV/atom\n", a0, e0);
  EXPECT_NEAR(a0, 3.615, 0.002);
  EXPECT_NEAR(e0, -3.54, 0.005);
  // The curve is a minimum: higher on both sides (fig. 7.2 shape).
  EXPECT_GT(energy(3.4), e0 + 0.05);
  EXPECT_GT(energy(3.9), e0 + 0.05);
}
