// The DPD/MPM grid (seed 004 sec. 3.2, steps s1-s14): particles in a uniform motion
// with no force translate exactly; the grid conserves the particles' total momentum to
// round-off when their pair forces sum to zero (s3b-s6: sum_p m_p a_p = sum_i f_i); one
// and two threads give the same bits; a particle leaving the grid stops the run, named;
// a concurrent run's continuum points (s3a, s10-s14) hold a uniform pre-stress in
// equilibrium and load the grid with -G . sigma V.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "../dpd/dpd_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/multiscale/dpd_grid.hpp"

namespace {

using namespace mpmx;

dpd::Particles rod(std::uint64_t seed) {
  dpd::Particles p = dpd::fcc_block({6, 3, 3}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  dpd::maxwell_velocities(p, 298.0, seed);
  return p;
}

multiscale::DpdGrid grid_over(const dpd::Particles& p, double cell, int threads = 1) {
  particles::Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x[3] = {p.x[i], p.y[i], p.z[i]};
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d] - 10), hi[d] = std::max(hi[d], x[d] + 10);
  }
  return multiscale::DpdGrid(cell, lo, hi, threads);
}

TEST(DpdGrid, UniformMotionTranslatesExactly) {
  dpd::Particles p = rod(1);
  for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = 1.5, p.vy[i] = -0.5, p.vz[i] = 0.25;
  const dpd::Particles start = p;
  auto g = grid_over(p, 4.0);
  g.move(p, 0.01);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p.vx[i], 1.5, 1e-13);
    EXPECT_NEAR(p.x[i], start.x[i] + 0.015, 1e-12);
    EXPECT_NEAR(p.y[i], start.y[i] - 0.005, 1e-12);
    EXPECT_NEAR(p.z[i], start.z[i] + 0.0025, 1e-12);
  }
}

TEST(DpdGrid, ConservesMomentumWhenTheForcesBalance) {
  dpd::Particles p = rod(2);
  // Pair-like forces: equal and opposite on consecutive particles.
  for (std::size_t i = 0; i + 1 < p.size(); i += 2) {
    const double f[3] = {0.3 * std::sin(0.7 * i), -0.2 * std::cos(0.3 * i), 0.1};
    p.fx[i] = f[0], p.fy[i] = f[1], p.fz[i] = f[2];
    p.fx[i + 1] = -f[0], p.fy[i + 1] = -f[1], p.fz[i + 1] = -f[2];
  }
  auto momentum = [&] {
    std::array<double, 3> m{};
    for (std::size_t i = 0; i < p.size(); ++i)
      m[0] += p.mass[i] * p.vx[i], m[1] += p.mass[i] * p.vy[i], m[2] += p.mass[i] * p.vz[i];
    return m;
  };
  const auto m0 = momentum();
  auto g = grid_over(p, 3.0);
  for (int s = 0; s < 20; ++s) g.move(p, 0.005);
  const auto m1 = momentum();
  const double scale = test::kCuMesoMass * std::sqrt(p.size()) * 1.0;
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(m1[d], m0[d], 1e-11 * scale) << d;
  EXPECT_EQ(g.skipped_nodes(), 0);
}

TEST(DpdGrid, SameBitsForOneAndTwoThreads) {
  dpd::Particles a = rod(3);
  for (std::size_t i = 0; i < a.size(); ++i) a.fx[i] = 0.01 * std::sin(1.3 * i), a.fz[i] = 0.02 * std::cos(i);
  dpd::Particles b = a;
  auto g1 = grid_over(a, 2.0, 1);
  auto g2 = grid_over(b, 2.0, 2);
  for (int s = 0; s < 5; ++s) g1.move(a, 0.005), g2.move(b, 0.005);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.x[i], b.x[i]);
    ASSERT_EQ(a.vz[i], b.vz[i]);
  }
}

TEST(DpdGrid, ParticleLeavingTheGridStopsTheRunNamed) {
  dpd::Particles p = rod(4);
  auto g = grid_over(p, 4.0);
  p.x[5] = 1e4;
  try {
    g.move(p, 0.005);
    FAIL() << "no error";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("particle 6"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("grid.margin"), std::string::npos) << e.what();
  }
}

TEST(DpdGrid, ContinuumPointsTakeTheirStressFromTheGridVelocityGradient) {
  // s10-s14: points of a block stretched at a uniform rate L_xx = 0.01/ps; over one step
  // of 0.01 ps an interior point takes sigma_xx = C11 1e-4 and sigma_yy = C12 1e-4. With
  // cells of the lattice constant every node sees the same points around it, so the
  // re-mapped nodal velocities are the linear field exactly (with half that, even and odd
  // nodes see the fcc basis differently and the gradient alternates by 6%).
  dpd::Particles p = dpd::fcc_block({6, 6, 6}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  for (auto& gid : p.group) gid = 0;
  auto g = grid_over(p, test::kCoarseLattice);  // every cell holds the whole fcc basis
  material::CubicConstants k{1.0, 0.5, 0.4};  // eV/A^3
  const double a = test::kCoarseLattice;
  g.set_continuum(0, std::make_unique<material::CubicElastic<3>>(k), p, a * a * a / 4);
  EXPECT_EQ(g.continuum_points(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) p.vx[i] = 0.01 * (p.x[i] - 3 * a);
  std::size_t mid = 0;
  double best = 1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = std::hypot(p.x[i] - 3 * a, p.y[i] - 3 * a, p.z[i] - 3 * a);
    if (r < best) best = r, mid = i;
  }
  const std::int64_t id = p.id[mid];
  g.move(p, 0.01);
  EXPECT_NEAR(g.continuum_stress(id, 0), 1.0e-4, 1e-12);
  EXPECT_NEAR(g.continuum_stress(id, 4), 0.5e-4, 1e-12);
  EXPECT_NEAR(g.continuum_stress(id, 1), 0.0, 1e-12);
}

}  // namespace
