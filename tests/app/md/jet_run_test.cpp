// The jet run's shock front (app/md/jet_run.hpp): where the column velocity crosses
// -up/2, interpolated between column centres.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/app/md/jet_run.hpp"

using namespace mpmx;
using namespace mpmx::md;
using namespace mpmx::app::md;

TEST(JetFront, InterpolatesWhereTheColumnVelocityCrossesHalfUp) {
  BinFields col;
  col.grid.nx = 6, col.grid.ny = 1, col.grid.x0 = 0, col.grid.dx = 2;
  col.atoms = {10, 10, 10, 10, 10, 0};
  col.vx = {0, -1, -5, -20, -25, 0};  // centres 1, 3, 5, 7, 9
  // Between x = 5 (v = -5) and 7 (v = -20): -12.5 at 5 + 2 * 7.5 / 15 = 6.
  EXPECT_NEAR(shock_front(col, 0.0, 25.0), 6.0, 1e-12);
  EXPECT_TRUE(std::isnan(shock_front(col, 8.0, 25.0)));  // first block column unshocked
  // Speed: the records inside (piston + width, tip(t) - width) only.
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4, 0.5}, x{1.0, 10.0, 15.0, 20.0, 25.0, 90.0};
  EXPECT_NEAR(shock_speed(t, x, 0.0, 100.0, 25.0, 5.0), 50.0, 1e-9);
  EXPECT_TRUE(std::isnan(shock_speed(t, x, 0.0, 20.0, 25.0, 5.0)));
}
