// Standing wave (ADMPM eqs. 8.9-8.10): values, boundary conditions, the linearised
// equations of motion (eq. 8.5) by finite differences, and bad parameters.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/standing_wave.hpp"

using mpmx::InputError;
using mpmx::reference::StandingWave;
namespace ref = mpmx::reference;

TEST(StandingWave, ValuesMatchIndependentlyComputedNumbers) {
  // Python: L=2, c=3, v0=0.02, n=2, rho0=1.5 at x=0.3, t=0.7.
  const StandingWave w{2.0, 3.0, 0.02, 2, 1.5};
  EXPECT_NEAR(ref::velocity(w, 0.3, 0.7), 0.015388417685876267, 1e-16);
  EXPECT_NEAR(ref::strain(w, 0.3, 0.7), 0.0012109042133422673, 1e-17);
  EXPECT_NEAR(ref::density(w, 0.3, 0.7), 1.5 * (1.0 - 0.0012109042133422673), 1e-15);
  EXPECT_NEAR(ref::stress(w, 0.3, 0.7), 1.5 * 9.0 * 0.0012109042133422673, 1e-15);
}

TEST(StandingWave, InitialStateIsEq811) {
  const StandingWave w{};  // the ADMPM case: L = 1, c = 1, v0 = 0.01, n = 1
  for (double x : {0.1, 0.5, 0.77}) {
    EXPECT_NEAR(ref::velocity(w, x, 0.0), 0.01 * std::sin(std::numbers::pi * x), 1e-16);
    EXPECT_EQ(ref::strain(w, x, 0.0), 0.0);
    EXPECT_EQ(ref::density(w, x, 0.0), 1.0);
  }
}

TEST(StandingWave, FixedEndsAndPeriod) {
  const StandingWave w{1.5, 2.0, 0.01, 3, 1.0};
  const double period = 2.0 * w.L / (w.n * w.c);
  for (double t : {0.0, 0.13, 0.9, 2.4}) {
    EXPECT_NEAR(ref::velocity(w, 0.0, t), 0.0, 1e-17);
    EXPECT_NEAR(ref::velocity(w, w.L, t), 0.0, 1e-16);
    EXPECT_NEAR(ref::velocity(w, 0.4, t + period), ref::velocity(w, 0.4, t), 1e-15);
    EXPECT_NEAR(ref::strain(w, 0.4, t + period), ref::strain(w, 0.4, t), 1e-15);
  }
}

TEST(StandingWave, SatisfiesLinearisedEquationsOfMotion) {
  // eq. 8.5b: rho0 v_t = E eps_x (E = rho0 c^2); kinematics eps_t = v_x;
  // eq. 8.5a: rho'_t + rho0 v_x = 0.
  const StandingWave w{1.0, 1.7, 0.01, 2, 2.0};
  const double h = 1e-5, E = w.rho0 * w.c * w.c;
  for (double x : {0.1, 0.35, 0.8})
    for (double t : {0.05, 0.4, 1.3}) {
      const double v_t = (ref::velocity(w, x, t + h) - ref::velocity(w, x, t - h)) / (2 * h);
      const double v_x = (ref::velocity(w, x + h, t) - ref::velocity(w, x - h, t)) / (2 * h);
      const double e_t = (ref::strain(w, x, t + h) - ref::strain(w, x, t - h)) / (2 * h);
      const double e_x = (ref::strain(w, x + h, t) - ref::strain(w, x - h, t)) / (2 * h);
      const double r_t = (ref::density(w, x, t + h) - ref::density(w, x, t - h)) / (2 * h);
      EXPECT_NEAR(w.rho0 * v_t, E * e_x, 1e-8);
      EXPECT_NEAR(e_t, v_x, 1e-8);
      EXPECT_NEAR(r_t + w.rho0 * v_x, 0.0, 1e-8);
    }
}

TEST(StandingWave, RejectsImpossibleParameters) {
  EXPECT_THROW(ref::velocity(StandingWave{0.0, 1.0, 0.01, 1, 1.0}, 0.5, 0.0), InputError);
  EXPECT_THROW(ref::velocity(StandingWave{1.0, -1.0, 0.01, 1, 1.0}, 0.5, 0.0), InputError);
  EXPECT_THROW(ref::strain(StandingWave{1.0, 1.0, 0.01, 0, 1.0}, 0.5, 0.0), InputError);
  EXPECT_THROW(ref::density(StandingWave{1.0, 1.0, 0.01, 1, 0.0}, 0.5, 0.0), InputError);
  EXPECT_THROW(ref::density(StandingWave{1.0, 1.0, NAN, 1, 1.0}, 0.5, 0.0), InputError);
}
