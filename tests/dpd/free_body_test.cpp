// A free rigid body (the seed's flyer "with initial velocity 5 Angstrom/ps", block key
// `free = true`): its particles keep one velocity, which follows the total pair force on
// it over its mass, so with conservative forces the flyer and target's total momentum is
// conserved to round-off, the flyer slows down as it pushes the target, and the same
// holds when a mover (the DPD/MPM grid) moves the particles.
#include <gtest/gtest.h>

#include <cmath>

#include "dpd_test_util.hpp"
#include "mpmx/multiscale/dpd_grid.hpp"

namespace {

using namespace mpmx;

dpd::System flyer_on_target() {
  const double a = test::kCoarseLattice;
  dpd::Particles target = dpd::fcc_block({6, 3, 3}, a, {2 * a, 0, 0}, test::kCuMesoMass, 0, 1);
  dpd::Particles flyer = dpd::fcc_block({2, 3, 3}, a, {0, 0, 0}, test::kCuMesoMass, 0, 10000);
  for (auto& g : flyer.group) g = 0;
  dpd::Particles all = target;
  dpd::append(all, flyer);
  dpd::Domain d = test::cube(3 * a, {false, false, false});
  d.box.lx = 8 * a;
  dpd::DpdParams par;  // conservative forces only
  dpd::System s(all, d, test::cu_meso_morse(12.0), par, {.skin = 1.0}, {{"flyer", {0, 0, 0}}});
  s.set_group_velocity(0, {5.0, 0, 0});
  s.release_group(0);
  return s;
}

double flyer_vx(const dpd::System& s) {
  for (std::size_t i = 0; i < s.particles().size(); ++i)
    if (s.particles().group[i] == 0) return s.particles().vx[i];
  return NAN;
}

TEST(DpdFreeBody, FlyerSlowsAndMomentumIsConserved) {
  dpd::System s = flyer_on_target();
  const particles::Vec3 p0 = s.momentum();
  s.advance(400, 0.005);
  const particles::Vec3 p1 = s.momentum();
  EXPECT_NEAR(p1[0], p0[0], 1e-9 * std::abs(p0[0]));
  EXPECT_NEAR(p1[1], p0[1], 1e-9 * std::abs(p0[0]));
  EXPECT_LT(flyer_vx(s), 4.0) << "the target pushed back on the flyer";
  const dpd::Particles& p = s.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.group[i] == 0) {
      ASSERT_EQ(p.vx[i], flyer_vx(s));
    }
  }
}

TEST(DpdFreeBody, SameWithTheGridMover) {
  dpd::System s = flyer_on_target();
  multiscale::DpdGrid grid(4.0, {-30, -30, -30}, {100, 60, 60});
  s.set_mover(&grid);
  const particles::Vec3 p0 = s.momentum();
  s.advance(400, 0.005);
  EXPECT_NEAR(s.momentum()[0], p0[0], 1e-9 * std::abs(p0[0]));
  EXPECT_LT(flyer_vx(s), 4.0);
}

}  // namespace
