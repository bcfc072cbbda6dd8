// ctest-label: slow
// A3: the small shock's front runs at the sound speed (ADMPM measured 1.039 c).
#include <gtest/gtest.h>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

TEST(A3, FrontSpeedWithinOnePercentOfC) {
  const auto r = test::run(test::deck(test::example("A3_small_shock.toml")));
  EXPECT_NEAR(r.front_speed, 1.0, 0.01);
}

TEST(A3, StrongerStepSameSpeedInTheLinearModel) {
  const auto r = test::run(test::deck(test::example("A3_small_shock_strain01.toml")));
  EXPECT_NEAR(r.front_speed, 1.0, 0.01);
}
