// Results independent of the thread count (bitwise, 1 vs 2 threads) and of the order in
// which the particles are given, for both integrators, over runs with neighbour
// rebuilds; the counter-based pair random numbers (symmetry, moments, independence).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>

#include "dpd_test_util.hpp"
#include "mpmx/dpd/pair_random.hpp"

namespace {

using namespace mpmx;

// Tiles of 100 particles: seven tiles, so the tiled pair forces' order is exercised.
dpd::System make(const dpd::Particles& p, bool dpde, int threads) {
  const test::SoftFluid f;
  dpd::DpdParams par;
  par.energy_conserving = dpde;
  par.integrator = dpde ? dpd::Integrator::shardlow : dpd::Integrator::velocity_verlet;
  par.gamma = f.gamma(), par.cutoff = f.rc, par.temperature = 300, par.seed = 77;
  par.heat_capacity = 10 * 8.617343e-5;
  return dpd::System(p, test::cube(42.0), f.potential(), par,
                     {.skin = 2.0, .threads = threads, .sort = true, .tile_particles = 100});
}

dpd::Particles start(std::uint64_t seed) {
  dpd::Particles p = dpd::random_block(700, {42.0, 42.0, 42.0}, {0, 0, 0}, 100.0, 0, 1, seed);
  dpd::maxwell_velocities(p, 300.0, seed + 1);
  for (auto& u : p.u) u = 10 * 8.617343e-5 * 300.0;
  return p;
}

// Fields by id (the engine sorts particles spatially; ids are stable).
std::vector<double> by_id(const dpd::Particles& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  std::vector<double> out;
  for (std::size_t i : order)
    for (const auto* v : {&p.x, &p.y, &p.z, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz, &p.u}) out.push_back((*v)[i]);
  return out;
}

void expect_bitwise_equal(const std::vector<double>& a, const std::vector<double>& b) {
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
  std::size_t diff = 0;
  for (std::size_t k = 0; k < a.size(); ++k) diff += a[k] != b[k];
  EXPECT_EQ(diff, 0u);
}

class DpdThreads : public ::testing::TestWithParam<bool> {};

TEST_P(DpdThreads, OneAndTwoThreadsGiveTheSameBits) {
  const bool dpde = GetParam();
  const test::SoftFluid f;
  const dpd::Particles p = start(12);
  dpd::System one = make(p, dpde, 1), two = make(p, dpde, 2), three = make(p, dpde, 3);
  one.advance(150, 0.04 * f.tau());
  two.advance(150, 0.04 * f.tau());
  three.advance(150, 0.04 * f.tau());
  EXPECT_GT(one.neighbor_builds(), 2);
  expect_bitwise_equal(by_id(one.particles()), by_id(two.particles()));
  expect_bitwise_equal(by_id(one.particles()), by_id(three.particles()));
  EXPECT_EQ(one.total_energy(), two.total_energy());
}

TEST_P(DpdThreads, ParticleOrderDoesNotChangeTheResult) {
  const bool dpde = GetParam();
  const test::SoftFluid f;
  const dpd::Particles p = start(13);
  dpd::Particles q = p;
  std::vector<std::size_t> order(q.size());
  std::iota(order.begin(), order.end(), 0);
  std::reverse(order.begin(), order.end());
  std::rotate(order.begin(), order.begin() + 101, order.end());
  q.permute(order);
  dpd::System a = make(p, dpde, 2), b = make(q, dpde, 1);
  a.advance(100, 0.04 * f.tau());
  b.advance(100, 0.04 * f.tau());
  expect_bitwise_equal(by_id(a.particles()), by_id(b.particles()));
}

INSTANTIATE_TEST_SUITE_P(Integrators, DpdThreads, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "ShardlowDpde" : "VelocityVerletDpd"; });

TEST(DpdPairRandom, SymmetricInThePairAndItsImage) {
  for (int s = 0; s < 5; ++s) {
    EXPECT_EQ(dpd::pair_key(9, s, 3, 17, 1, 0, -1), dpd::pair_key(9, s, 17, 3, -1, 0, 1));
    EXPECT_EQ(dpd::pair_key(9, s, 5, 5, 0, 1, 0), dpd::pair_key(9, s, 5, 5, 0, -1, 0));
    EXPECT_NE(dpd::pair_key(9, s, 3, 17, 1, 0, -1), dpd::pair_key(9, s, 3, 17, 0, 0, 0));
    EXPECT_NE(dpd::pair_key(9, s, 3, 17, 0, 0, 0), dpd::pair_key(9, s + 1, 3, 17, 0, 0, 0));
    EXPECT_NE(dpd::pair_key(9, s, 3, 17, 0, 0, 0), dpd::pair_key(10, s, 3, 17, 0, 0, 0));
  }
}

TEST(DpdPairRandom, StandardNormalMomentsAndNoCorrelation) {
  // 2e6 draws over pairs and steps: mean 0, variance 1, kurtosis 3 (errors ~ 1e-3), and
  // no correlation between a pair's numbers at successive steps or between neighbours.
  double m1 = 0, m2 = 0, m4 = 0, c_step = 0, c_pair = 0;
  const int steps = 2000, pairs = 1000;
  long n = 0;
  for (int s = 0; s < steps; ++s)
    for (int k = 0; k < pairs; ++k) {
      const double t = dpd::pair_normal(dpd::pair_key(42, s, k, k + 1, 0, 0, 0));
      const double t_next = dpd::pair_normal(dpd::pair_key(42, s + 1, k, k + 1, 0, 0, 0));
      const double t_nb = dpd::pair_normal(dpd::pair_key(42, s, k, k + 2, 0, 0, 0));
      m1 += t, m2 += t * t, m4 += t * t * t * t, c_step += t * t_next, c_pair += t * t_nb;
      ++n;
    }
  m1 /= n, m2 /= n, m4 /= n, c_step /= n, c_pair /= n;
  EXPECT_NEAR(m1, 0.0, 0.004);
  EXPECT_NEAR(m2, 1.0, 0.005);
  EXPECT_NEAR(m4, 3.0, 0.03);
  EXPECT_NEAR(c_step, 0.0, 0.004);
  EXPECT_NEAR(c_pair, 0.0, 0.004);
}

}  // namespace
