// ctest-label: validation
// Direct-MD bar (chapter 6 reference): reflecting walls conserve atoms and energy; the
// compressed left half starts at sigma_xx = C11 e0 and releases a wave that travels at
// about the longitudinal sound speed sqrt(C11/rho) while the far end is still at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/md/bar.hpp"

#include "../md/md_test_util.hpp"

using namespace mpmx::md;

namespace {
using mpmx::test::copper;
}  // namespace

TEST(Bar, ReleaseWaveFromCompressedHalf) {
  BarConfig c;
  c.cells_x = 40;
  c.cells_yz = 3;
  c.strain_left = -0.005;
  c.bins = 40;  // one slab per cell, the split at slab 20
  Bar bar(c, copper());
  const auto s0 = bar.slab_stress_gpa();
  // Interior of the compressed half: sigma_xx about C11 e0 = -0.85 GPa (Cauchy sign).
  std::printf("bar t=0: left %.3f GPa, right %.3f GPa\n", s0[10][0], s0[30][0]);
  EXPECT_NEAR(s0[10][0], 169.9 * c.strain_left, 0.1);
  EXPECT_NEAR(s0[30][0], 0.0, 0.05);
  const double e0 = bar.system().potential_energy() + bar.system().kinetic_energy();
  const std::size_t n = bar.system().atoms().size();

  bar.advance(400, 0.001);  // 0.4 ps: the front moves about 18 Angstrom (~5 slabs)
  const auto s1 = bar.slab_stress_gpa();
  const auto x = bar.slab_centres();
  const Walls& w = bar.system().walls();
  for (int b = 0; b < c.bins; ++b) std::printf("%s%.2f", b ? " " : "bar t=0.4 ps sxx: ", s1[b][0]);
  std::printf("\n");
  EXPECT_LT(s1[22][0], -0.2);             // the compression has spread past the middle
  EXPECT_NEAR(s1[30][0], 0.0, 0.05);      // not yet this far (front ~18 A = 5 slabs)
  EXPECT_GT(s1[17][0], s0[17][0] + 0.2);  // released behind the left-going rarefaction
  EXPECT_NEAR(s1[10][0], s0[10][0], 0.1); // which has not reached here yet
  (void)x;
  const Atoms a = bar.system().atoms();
  ASSERT_EQ(a.size(), n);
  for (std::size_t i = 0; i < n; ++i) ASSERT_TRUE(a.x[i] >= w.lo && a.x[i] <= w.hi);
  const double e1 = bar.system().potential_energy() + bar.system().kinetic_energy();
  EXPECT_NEAR((e1 - e0) / n, 0.0, 2e-5);  // fixed reflecting walls do no work
}

TEST(Bar, MovingPistonDoesWork) {
  BarConfig c;
  c.cells_x = 12;
  c.cells_yz = 3;
  c.bins = 12;
  c.piston_velocity = 5.0;  // 500 m/s into the bar
  Bar bar(c, copper());
  const double e0 = bar.system().potential_energy() + bar.system().kinetic_energy();
  bar.advance(200, 0.001);
  const double e1 = bar.system().potential_energy() + bar.system().kinetic_energy();
  EXPECT_GT(e1 - e0, 1.0);  // the piston compresses the bar
  const Walls& w = bar.system().walls();
  EXPECT_NEAR(w.v_lo, 5.0, 0.0);
  for (double xa : bar.system().atoms().x) EXPECT_GE(xa, w.lo);
}
