// Ideal-gas wave (ADMPM eq. 7.8): sound speed, drive, the linear acoustic equations by
// finite differences (this fixes the sign of p' for each travelling component), and
// agreement with the elastic-bar solution through p' = -sigma = -rho0 c^2 eps.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/gas_wave.hpp"
#include "mpmx/reference/wave_reflection.hpp"

using mpmx::InputError;
using mpmx::reference::GasWave;
namespace ref = mpmx::reference;

TEST(GasWave, SoundSpeedIsEq78a) {
  EXPECT_NEAR(ref::sound_speed(GasWave{1.0, 1.4, 1e5, 1.2, 0.01, 10.0}), 341.56502553198663, 1e-10);
  EXPECT_DOUBLE_EQ(ref::sound_speed(GasWave{}), 1.0);  // the ADMPM case gamma = rho0 = p0 = 1
  EXPECT_DOUBLE_EQ(ref::end_time(GasWave{2.0, 4.0, 1.0, 1.0, 0.01, 10.0}), 2.0);
}

TEST(GasWave, VelocityIsEq78bAndDriveHolds) {
  const GasWave g{};  // c = 1, L = 1, v0 = 0.01, omega = 10
  EXPECT_EQ(ref::velocity(g, 0.3, 0.5), 0.0);
  EXPECT_NEAR(ref::velocity(g, 0.9, 0.5), 0.01 * std::sin(10.0 * (-0.1 + 0.5)), 1e-16);
  // Third branch of eq. 7.8b, written independently.
  EXPECT_NEAR(ref::velocity(g, 0.1, 1.4), 2 * 0.01 * std::sin(10.0 * 0.1) * std::cos(10.0 * 0.4), 1e-16);
  for (double t : {0.2, 0.7, 1.3, 1.9}) {
    EXPECT_NEAR(ref::velocity(g, 1.0, t), 0.01 * std::sin(10.0 * t), 1e-16);
    EXPECT_NEAR(ref::velocity(g, 0.0, t), 0.0, 1e-17);
  }
}

TEST(GasWave, PressureSignsSatisfyLinearAcoustics) {
  // rho0 v_t = -p_x and p_t = -rho0 c^2 v_x (= -gamma p0 v_x), rho' = p'/c^2.
  const GasWave g{1.0, 1.4, 2.0, 1.5, 0.01, 9.0};
  const double c = ref::sound_speed(g), h = 1e-6;
  struct P {
    double x, t;
  };
  for (P p : {P{0.9, 0.3}, P{0.6, 0.55}, P{0.2, 1.3}, P{0.05, 1.4}, P{0.9, 1.3}}) {
    const double v_t = (ref::velocity(g, p.x, p.t + h) - ref::velocity(g, p.x, p.t - h)) / (2 * h);
    const double v_x = (ref::velocity(g, p.x + h, p.t) - ref::velocity(g, p.x - h, p.t)) / (2 * h);
    const double p_t = (ref::pressure(g, p.x, p.t + h) - ref::pressure(g, p.x, p.t - h)) / (2 * h);
    const double p_x = (ref::pressure(g, p.x + h, p.t) - ref::pressure(g, p.x - h, p.t)) / (2 * h);
    EXPECT_NEAR(g.rho0 * v_t, -p_x, 1e-7) << "x=" << p.x << " t=" << p.t;
    EXPECT_NEAR(p_t, -g.gamma * g.p0 * v_x, 1e-7) << "x=" << p.x << " t=" << p.t;
    EXPECT_GT(std::abs(p_x), 1e-3);
    EXPECT_NEAR(ref::density_perturbation(g, p.x, p.t), ref::pressure_perturbation(g, p.x, p.t) / (c * c), 1e-18);
    EXPECT_NEAR(ref::density(g, p.x, p.t), g.rho0 + ref::density_perturbation(g, p.x, p.t), 1e-15);
  }
  // Piston pulled outward (v > 0 at x = L) expands the gas: p' < 0 there.
  EXPECT_LT(ref::pressure_perturbation(g, 0.99, 0.05), 0.0);
}

TEST(GasWave, MatchesElasticBarThroughStress) {
  // Same linear system with Y = rho0 c^2 and p' = -sigma.
  const GasWave g{1.3, 1.4, 1.0, 1.0, 0.02, 6.0};
  const double c = ref::sound_speed(g);
  const ref::WaveReflection w{g.L, c, g.v0, g.omega, g.rho0};
  for (double t : {0.1, 0.6, 1.2, 1.8, 2.1})
    for (double x : {0.05, 0.4, 0.8, 1.25}) {
      EXPECT_NEAR(ref::velocity(g, x, t), ref::velocity(w, x, t), 1e-15);
      EXPECT_NEAR(ref::pressure_perturbation(g, x, t), -ref::stress(w, x, t), 1e-15);
    }
}

TEST(GasWave, RejectsTimesOutsideValidityAndBadParameters) {
  const GasWave g{};
  EXPECT_THROW(ref::velocity(g, 0.5, 2.1), InputError);
  EXPECT_THROW(ref::pressure(g, 0.5, -1.0), InputError);
  EXPECT_THROW(ref::sound_speed(GasWave{1.0, 0.0, 1.0, 1.0, 0.01, 10.0}), InputError);
  EXPECT_THROW(ref::sound_speed(GasWave{1.0, 1.4, -1.0, 1.0, 0.01, 10.0}), InputError);
  EXPECT_THROW(ref::velocity(GasWave{0.0, 1.4, 1.0, 1.0, 0.01, 10.0}, 0.0, 0.0), InputError);
}
