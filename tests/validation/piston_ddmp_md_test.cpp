// ctest-label: validation
// ctest-cost: 60
// C1 (VALIDATION.md), the multiscale bar: a piston drives the H2 DDMP-MD copper bar
// (every point's stress from its own 256-atom MD box), and the same bar moving at -u_p
// onto a fixed wall (the seed's way) gives the same front and plateau in the piston's
// frame.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

struct Profile {
  double velocity = 0.0, stress = 0.0, front = 0.0;  // plateau means; the front by point index
};

// The plateau: points 3-13 (between the first points, which carry the start's ringing,
// and the front near point 18 at t = 3 ps); the front: where sigma falls through half
// the plateau's, interpolated between point indices (points are one cell apart at rest).
Profile profile(const mpm::Particles<1>& p) {
  Profile r;
  for (std::size_t q = 3; q < 14; ++q) r.velocity += p.v[0][q] / 11.0, r.stress += p.stress[0][q] / 11.0;
  for (std::size_t q = 10; q + 1 < p.size(); ++q)
    if (p.stress[0][q] <= 0.5 * r.stress && p.stress[0][q + 1] > 0.5 * r.stress) {
      r.front = q + (0.5 * r.stress - p.stress[0][q]) / (p.stress[0][q + 1] - p.stress[0][q]);
      break;
    }
  return r;
}

}  // namespace

TEST(C1, DdmpMdBarPistonAndWallImpactAgree) {
  const double up = 0.2;
  const auto piston = test::deck(test::example("C1_piston_ddmp_md_small.toml"));
  const auto wall = test::deck_with(test::example("C1_piston_ddmp_md_small.toml"), [&](toml::table& t) {
    t["boundary"].as_table()->insert_or_assign("left", toml::table{{"type", "fixed"}});
    t.insert_or_assign("initial", toml::table{{"velocity", toml::table{{"value", -up}}}});
  });
  const Profile a = profile(test::run(piston).state.particles);
  const Profile b = profile(test::run(wall).state.particles);
  std::printf("piston: u %.4f sigma %.3f front %.2f; wall: u %+.4f sigma %.3f front %.2f; differences %.2g %.2g %.2g\n",
              a.velocity, a.stress, a.front, b.velocity, b.stress, b.front, a.velocity - up - b.velocity,
              a.stress - b.stress, a.front - b.front);
  EXPECT_NEAR(a.velocity, up, 0.01 * up);  // behind the front: the piston's speed
  EXPECT_NEAR(b.velocity, 0.0, 0.01 * up);  // brought to rest by the wall
  EXPECT_LT(a.stress, -7.0);                // a strong shock: about -8 GPa
  EXPECT_GT(a.front, 15.0);
  // The piston carries the grid (mpm/piston_grid.hpp): in its frame it is the wall, point
  // for point (the boxes see only the deformation; the bar's far end, where the runs
  // differ, has not reached the plateau).
  EXPECT_NEAR(a.velocity - up, b.velocity, 1e-5 * up);
  EXPECT_NEAR(a.stress, b.stress, 1e-5 * std::abs(b.stress));
  EXPECT_NEAR(a.front, b.front, 0.01);
}
