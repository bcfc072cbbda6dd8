// DPDE with the Shardlow splitting conserves energy (seed 004 sec. 2.2; issue 16): in
// NVE, kinetic + conservative + internal energy drifts by less than 1e-4 of the kinetic
// energy per 1000 steps at the seed's gamma = 0.2 amu/ps (and at a gamma 10 times
// larger: the stochastic sweep conserves the energy, velocity Verlet its shadow energy,
// and the kicks between them make the energy wander by O(dt^2), more with more gamma:
// about 1e-4 per 1000 steps at 100 x 0.2 amu/ps); one stochastic sweep alone conserves it to round-off; heat flows from hot
// internal degrees of freedom to the mesoparticles' motion until both temperatures agree
// at the heat-capacity weighted mean.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dpd_test_util.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/shardlow.hpp"

namespace {

using namespace mpmx;

// Cu mesoparticle crystal (Morse, 6^3 fcc cells = 864 particles) at 298 K, periodic.
dpd::System cu_crystal(double gamma, double t_kinetic, double t_internal, int threads = 1) {
  const int n = 6;
  dpd::Particles p = dpd::fcc_block({n, n, n}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  dpd::maxwell_velocities(p, 2 * t_kinetic, 17);  // half goes to potential energy
  for (auto& u : p.u) u = test::kCuMesoCv * t_internal;
  dpd::DpdParams par;
  par.energy_conserving = true;
  par.gamma = gamma;
  par.cutoff = 12.0;
  par.heat_capacity = test::kCuMesoCv;
  par.seed = 2014;
  return dpd::System(p, test::cube(n * test::kCoarseLattice), test::cu_meso_morse(12.0), par,
                     {.skin = 1.0, .threads = threads});
}

struct Drift {
  double slope_per_1000 = 0;  // least-squares slope of E(t) times 1000 steps, over mean K
  double end_to_end = 0;      // mean E of the last 100 steps less that of the first 100, over mean K
  double fluctuation = 0;     // standard deviation of E about its trend, over mean K
};

Drift energy_drift(dpd::System& s, int steps, double dt) {
  std::vector<double> e, k;
  for (int i = 0; i <= steps; ++i) {
    if (i > 0) s.advance(1, dt);
    e.push_back(s.total_energy());
    k.push_back(s.kinetic_energy());
  }
  double mk = 0, mt = 0, me = 0;
  for (int i = 0; i <= steps; ++i) mk += k[i], mt += i, me += e[i];
  mk /= steps + 1, mt /= steps + 1, me /= steps + 1;
  double sxy = 0, sxx = 0;
  for (int i = 0; i <= steps; ++i) sxy += (i - mt) * (e[i] - me), sxx += (i - mt) * (i - mt);
  const double slope = sxy / sxx;
  double head = 0, tail = 0, var = 0;
  for (int i = 0; i < 100; ++i) head += e[i] / 100, tail += e[steps - i] / 100;
  for (int i = 0; i <= steps; ++i) var += std::pow(e[i] - me - slope * (i - mt), 2) / (steps + 1);
  return {std::abs(slope) * 1000 / mk, std::abs(tail - head) / mk, std::sqrt(var) / mk};
}

TEST(DpdeEnergy, DriftBelow1e4OfKineticPer1000StepsAtSeedGamma) {
  dpd::System s = cu_crystal(test::kSeedGamma, 298.0, 298.0);
  s.advance(200, 0.005);  // settle the lattice vibrations
  const Drift d = energy_drift(s, 1000, 0.005);
  std::printf("gamma 0.2 amu/ps, dt 5 fs: drift %.3g of K per 1000 steps (slope), last-100 less first-100 %.3g, "
              "fluctuation %.3g, T %.1f K, T_int %.1f K\n",
              d.slope_per_1000, d.end_to_end, d.fluctuation, s.temperature(), s.internal_temperature());
  EXPECT_LT(d.slope_per_1000, 1e-4);
  EXPECT_LT(d.end_to_end, 1e-4);
}

TEST(DpdeEnergy, DriftBelow1e4AtTenTimesTheSeedGamma) {
  dpd::System s = cu_crystal(10 * test::kSeedGamma, 298.0, 298.0);
  s.advance(600, 0.005);  // internal and kinetic temperatures settle together
  const Drift d = energy_drift(s, 1000, 0.005);
  std::printf("gamma 2 amu/ps: drift %.3g of K per 1000 steps (slope), last-100 less first-100 %.3g, "
              "fluctuation %.3g\n", d.slope_per_1000, d.end_to_end, d.fluctuation);
  EXPECT_LT(d.slope_per_1000, 1e-4);
  EXPECT_LT(d.end_to_end, 1e-4);
}

TEST(DpdeEnergy, OneSweepConservesEnergyToRoundOff) {
  dpd::System s = cu_crystal(100 * test::kSeedGamma, 298.0, 600.0);
  s.advance(10, 0.005);
  dpd::PairList list;
  dpd::Particles p = s.particles();
  list.build(p, s.domain(), 12.0, 1.0, true);
  auto energy = [](const dpd::Particles& q) {
    double k = 0, u = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      k += 0.5 * q.mass[i] * (q.vx[i] * q.vx[i] + q.vy[i] * q.vy[i] + q.vz[i] * q.vz[i]) * units::mvv2e;
      u += q.u[i];
    }
    return std::pair{k, u};
  };
  const auto [k0, u0] = energy(p);
  dpd::SweepParams sp;
  sp.gamma = 100 * test::kSeedGamma, sp.cutoff = 12.0, sp.dt = 0.005, sp.energy_conserving = true;
  sp.heat_capacity = test::kCuMesoCv, sp.seed = 5, sp.step = 10;
  dpd::SweepWork work;
  dpd::shardlow_sweep(list, p, sp, work, 1);
  const auto [k1, u1] = energy(p);
  EXPECT_GT(std::abs(k1 - k0), 1e-6 * k0) << "the sweep exchanged energy";
  EXPECT_LT(std::abs((k1 + u1) - (k0 + u0)), 1e-13 * (k0 + u0));
}

TEST(DpdeEnergy, HotInternalDegreesOfFreedomHeatTheMotion) {
  // Internal 900 K, mechanical 150 K (kinetic 300 K at the start, half of it going into
  // the lattice's potential energy), strong coupling: both meet at the heat-capacity
  // weighted mean, (21 x 900 + 3 x 150) / 24 = 806 K (the harmonic crystal's 3 k_B per
  // particle against C_v = 21 k_B), while the total energy stays put.
  dpd::System s = cu_crystal(400 * test::kSeedGamma, 150.0, 900.0);
  const double e0 = s.total_energy();
  const double t_int0 = s.internal_temperature();
  s.advance(3000, 0.005);
  double tk = 0, ti = 0;
  for (int b = 0; b < 20; ++b) {
    s.advance(10, 0.005);
    tk += s.temperature() / 20, ti += s.internal_temperature() / 20;
  }
  const double want = (21 * 900.0 + 3 * 150.0) / 24;
  std::printf("T kinetic 300 -> %.1f K, internal %.1f -> %.1f K, expected both near %.1f K\n", tk, t_int0, ti, want);
  EXPECT_NEAR(tk, want, 0.05 * want);
  EXPECT_NEAR(ti, want, 0.02 * want);
  // The energy moves only by the velocity-Verlet offset of order dt^2 following the
  // state (0.26 eV at dt = 5 fs, 0.067 eV at 2.5 fs): below 0.5% of the kinetic energy.
  EXPECT_LT(std::abs(s.total_energy() - e0), 5e-3 * s.kinetic_energy());
}

}  // namespace
