// ctest-label: unit
// The 0 K copper crystal's tangent moduli under compression (md/compression_moduli.hpp):
// at J = 1 the uniaxial modulus is C11 of the elastic constants, the stiffness grows under
// compression, and a 2.5 km/s shock (the copper jet's impact) reaches the J and the wave
// speed that the direct MD's shock (Us 7.7 km/s: J = 1 - 2.5 / 7.7 = 0.675) and copper's
// Hugoniot put there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "md_test_util.hpp"
#include "mpmx/md/compression_moduli.hpp"
#include "mpmx/md/equilibrium.hpp"

using namespace mpmx;

TEST(CompressionModuli, CopperFromRestToTheJetsShock) {
  const md::Potential pot = test::copper();
  const md::FccEquilibrium eq = md::fcc_equilibrium(pot);
  particles::LatticeSpec spec;
  spec.constant = eq.lattice_constant;
  const md::CompressionModuli t = md::compression_moduli(pot, spec);
  ASSERT_EQ(t.J.size(), 71u);
  // The row at J = 1 (0.5 + 50 x 0.01): the uniaxial modulus along each cube axis is C11.
  const std::size_t one = 50;
  ASSERT_NEAR(t.J[one], 1.0, 1e-12);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(t.uniaxial_modulus[a][one], eq.c11_gpa, 1e-3 * eq.c11_gpa);
    EXPECT_NEAR(t.uniaxial[a][one], 0.0, 1e-3);
  }
  EXPECT_NEAR(t.modulus[one], eq.c11_gpa, 1e-3 * eq.c11_gpa);
  // Never softer under more compression (the table's envelope), and 9 times stiffer at J 0.6.
  for (std::size_t k = 1; k <= one; ++k) EXPECT_GE(t.modulus[k - 1], t.modulus[k]) << "J = " << t.J[k];
  EXPECT_GT(t.modulus[10], 8.0 * eq.c11_gpa);
  // The shock: copper's density 8.94 g/cm^3 in nm_ps_GPa's units (1 g/cm^3 = 1 GPa ps^2 / nm^2).
  const double rho0 = eq.density_amu_per_A3 * 1.66053906660;  // amu / A^3 -> g/cm^3
  const double J = t.shock_compression(0, 2.5, rho0, 1.0);
  const double c = std::sqrt(t.modulus_at(J) * J / rho0);
  std::printf("copper 0 K: C11 %.1f GPa, rho %.4f; up 2.5 km/s: J %.4f, Us %.3f km/s, P %.1f GPa, c %.3f km/s "
              "(M %.0f GPa)\n",
              eq.c11_gpa, rho0, J, 2.5 / (1 - J), rho0 * 2.5 * 2.5 / (1 - J), c, t.modulus_at(J));
  for (double j : {0.6, 0.65, 0.6686, 0.675, 0.7, 0.8, 0.9, 1.0, 1.1})
    std::printf("  J %.2f: M %.0f GPa, c %.3f km/s\n", j, t.modulus_at(j), std::sqrt(t.modulus_at(j) * j / rho0));
  EXPECT_GT(J, 0.60);
  EXPECT_LT(J, 0.75);
  EXPECT_GT(c, 6.5);
  EXPECT_LT(c, 11.0);
}
