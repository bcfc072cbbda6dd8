// Nelder-Mead (core/nelder_mead.hpp), the optimiser of the MD-to-DPD fit: it finds a
// known minimum, deterministically.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpmx/core/nelder_mead.hpp"

using namespace mpmx;

TEST(NelderMead, FindsTheRosenbrockMinimumDeterministically) {
  auto rosen = [](const std::vector<double>& x) {
    return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
  };
  const auto a = nelder_mead(rosen, {-1.2, 1.0}, {0.1, 0.1}, 5000, 1e-20);
  const auto b = nelder_mead(rosen, {-1.2, 1.0}, {0.1, 0.1}, 5000, 1e-20);
  EXPECT_NEAR(a.x[0], 1.0, 1e-5);
  EXPECT_NEAR(a.x[1], 1.0, 1e-5);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.evaluations, b.evaluations);
}
