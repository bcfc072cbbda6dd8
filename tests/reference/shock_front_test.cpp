// Shock-front location and speed (ADMPM sec. 8.3).
// ctest-label: unit
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/shock_front.hpp"

using mpmx::InputError;
using mpmx::reference::ScanFrom;
namespace ref = mpmx::reference;

TEST(ShockFront, LinearInterpolationOfTheMidpointCrossing) {
  // Strain -0.001 on the left, 0 on the right, one ramp sample in between.
  const std::vector<double> x{0.0, 0.1, 0.2, 0.3, 0.4};
  const std::vector<double> f{-0.001, -0.001, -0.0008, 0.0, 0.0};
  // Midpoint -0.0005 is crossed between x = 0.2 (-0.0008) and 0.3 (0): 0.2 + 0.1 * 3/8.
  EXPECT_NEAR(*ref::locate_front(x, f, -0.001, 0.0, ScanFrom::right), 0.2375, 1e-15);
  EXPECT_NEAR(*ref::locate_front(x, f, 0.0, -0.001, ScanFrom::left), 0.2375, 1e-15);
}

TEST(ShockFront, ScanSideSelectsWhichFront) {
  // Two fronts of a pulse (the A3 case has one moving each way); order shuffled.
  std::vector<double> x, f;
  for (int i = 0; i <= 100; ++i) {
    const double xi = 0.01 * i;
    x.push_back(xi);
    f.push_back(0.5 * (std::tanh((xi - 0.3131) / 0.02) - std::tanh((xi - 0.7217) / 0.02)));
  }
  std::reverse(x.begin(), x.end());
  std::reverse(f.begin(), f.end());
  std::swap(x[3], x[50]);
  std::swap(f[3], f[50]);
  EXPECT_NEAR(*ref::locate_front(x, f, 0.0, 1.0, ScanFrom::left), 0.3131, 2e-4);
  EXPECT_NEAR(*ref::locate_front(x, f, 0.0, 1.0, ScanFrom::right), 0.7217, 2e-4);
  EXPECT_FALSE(ref::locate_front(x, f, 2.0, 3.0, ScanFrom::left).has_value());
}

TEST(ShockFront, ExactSampleOnTheMidpoint) {
  const std::vector<double> x{0.0, 1.0, 2.0};
  const std::vector<double> f{0.0, 0.5, 1.0};
  EXPECT_DOUBLE_EQ(*ref::locate_front(x, f, 0.0, 1.0, ScanFrom::left), 1.0);
  EXPECT_DOUBLE_EQ(*ref::locate_front(x, f, 0.0, 1.0, ScanFrom::right), 1.0);
}

TEST(ShockFront, LeastSquaresSpeed) {
  // x = 0.5 + 1.039 t with alternating +-1e-3 noise: slope of that noise pattern is
  // computed by hand (t = 0, .1, .2, .3 with noise +,-,+,-): sum (t - tm) n / sum (t - tm)^2
  // = (-.15 * 1e-3 - .05 * -1e-3 + .05 * 1e-3 + .15 * -1e-3) / 0.05 = -0.004.
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3};
  std::vector<double> x;
  for (std::size_t i = 0; i < t.size(); ++i) x.push_back(0.5 + 1.039 * t[i] + (i % 2 ? -1e-3 : 1e-3));
  const ref::FrontLine line = ref::fit_front_line(t, x);
  EXPECT_NEAR(line.speed, 1.039 - 0.004, 1e-12);
  EXPECT_NEAR(ref::front_speed(t, x), 1.035, 1e-12);
  EXPECT_NEAR(line.x0, 0.5 + 0.0006, 1e-12);  // mean noise 0, intercept shifted by 0.004 * tm
}

TEST(ShockFront, RejectsBadInput) {
  const std::vector<double> a{0.0, 1.0}, b{0.0}, same{1.0, 1.0}, bad{0.0, NAN};
  EXPECT_THROW(ref::locate_front(a, b, 0.0, 1.0, ScanFrom::left), InputError);
  EXPECT_THROW(ref::locate_front(b, b, 0.0, 1.0, ScanFrom::left), InputError);
  EXPECT_THROW(ref::locate_front(a, a, 1.0, 1.0, ScanFrom::left), InputError);
  EXPECT_THROW(ref::locate_front(a, bad, 0.0, 1.0, ScanFrom::left), InputError);
  EXPECT_THROW(ref::fit_front_line(same, a), InputError);
  EXPECT_THROW(ref::fit_front_line(b, b), InputError);
  EXPECT_THROW(ref::front_speed(a, b), InputError);
}
