// ctest-label: validation
// M4 (fig. 5.4 with Cu): uniaxial strain of a periodic fcc Cu box at 0 K through the
// box deformation of eqs. 5.7-5.8. The initial slope of sigma_xx against the strain is
// C11 = 169.9 GPa (Mishin Cu) within 2%, whatever the atom count (256, 500) and rate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "m4_uniaxial.hpp"

using mpmx::test::uniaxial_slope;
using namespace mpmx::md;

TEST(M4, SlopeIsC11At1e9) {
  const double c11 = 169.9;
  for (int cells : {4, 5}) {
    const double k = uniaxial_slope(cells, 1e9, 0.002, Deformation::boundary);
    std::printf("M4: %d atoms, 1e9/s, 0 K: slope %.2f GPa (C11 %.1f, %.2f%%)\n", 4 * cells * cells * cells, k,
                c11, 100 * (k / c11 - 1));
    EXPECT_NEAR(k, c11, 0.02 * c11) << cells;
  }
}

TEST(M4, AffineDeformationGivesTheSameSlope) {
  const double k = uniaxial_slope(4, 1e9, 0.002, Deformation::affine);
  std::printf("M4: 256 atoms, affine, 1e9/s: slope %.2f GPa\n", k);
  EXPECT_NEAR(k, 169.9, 0.02 * 169.9);
}
