// ctest-label: slow
// Fluctuation-dissipation (seed 004 eqs. 2.4-2.5 with sigma^2 = 2 gamma k_B T): an
// isothermal DPD fluid (Groot-Warren a = 25 kT/rc, gamma = 4.5, density 3/rc^3, in
// metal units) settles at the bath temperature: the time-averaged kinetic temperature
// is within 1% of the set one, with the velocity-Verlet integrator (LAMMPS pair dpd +
// fix nve) at dt = 0.01 tau and with the Shardlow splitting at 0.02 tau (at 0.04 tau it
// runs about 1% warm: the conservative part's velocity Verlet error).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dpd_test_util.hpp"

namespace {

using namespace mpmx;

struct Mean {
  double mean = 0, error = 0;  // time average and its standard error from 20 blocks
};

Mean average_temperature(dpd::Integrator integrator, double dt_tau, int steps) {
  const test::SoftFluid f;
  const double l = std::cbrt(1500 / 3.0) * f.rc;  // 1500 particles at density 3/rc^3
  dpd::Particles p = dpd::random_block(1500, {l, l, l}, {0, 0, 0}, f.mass, 0, 1, 99);
  dpd::maxwell_velocities(p, f.temperature, 100);
  dpd::DpdParams par;
  par.integrator = integrator;
  par.gamma = f.gamma(), par.cutoff = f.rc, par.temperature = f.temperature, par.seed = 4242;
  dpd::System s(p, test::cube(l), f.potential(), par, {.skin = 3.0, .threads = 1});
  const double dt = dt_tau * f.tau();
  s.advance(static_cast<int>(5.0 / dt_tau), dt);  // 5 tau from the random start
  const int blocks = 20, per = steps / blocks;
  double sum = 0, sum2 = 0;
  for (int b = 0; b < blocks; ++b) {
    double bt = 0;
    for (int k = 0; k < per; ++k) {
      s.advance(1, dt);
      bt += s.temperature() / per;
    }
    sum += bt, sum2 += bt * bt;
  }
  const double mean = sum / blocks;
  return {mean, std::sqrt(std::max(0.0, sum2 / blocks - mean * mean) / (blocks - 1))};
}

TEST(FluctuationDissipation, VelocityVerletDpdHoldsTheBathTemperature) {
  const Mean t = average_temperature(dpd::Integrator::velocity_verlet, 0.01, 20000);
  std::printf("velocity Verlet, dt = 0.01 tau: <T> = %.2f +- %.2f K (set 300 K, %.2f%%)\n", t.mean, t.error,
              100 * (t.mean / 300 - 1));
  EXPECT_NEAR(t.mean, 300.0, 3.0);
  EXPECT_LT(t.error, 1.0);
}

TEST(FluctuationDissipation, ShardlowDpdHoldsTheBathTemperatureAtTwiceTheStep) {
  const Mean t = average_temperature(dpd::Integrator::shardlow, 0.02, 10000);
  std::printf("Shardlow, dt = 0.02 tau: <T> = %.2f +- %.2f K (set 300 K, %.2f%%)\n", t.mean, t.error,
              100 * (t.mean / 300 - 1));
  EXPECT_NEAR(t.mean, 300.0, 3.0);
  EXPECT_LT(t.error, 1.0);
}

}  // namespace
