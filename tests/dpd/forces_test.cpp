// DPD pair forces: the conservative forces, energy and virial against a brute-force sum
// over all images (periodic, open axes, a box smaller than twice the cutoff); forces
// minus the energy gradient for every registered potential; momentum conserved by the
// pair forces (conservative, dissipative and random) to round-off, at one evaluation and
// over runs of both integrators.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "dpd_test_util.hpp"
#include "mpmx/dpd/forces.hpp"
#include "mpmx/dpd/pair_list.hpp"

namespace {

using namespace mpmx;
using test::cube;

dpd::Particles fluid(long n, double l, std::uint64_t seed, double mass = 100.0) {
  return dpd::random_block(n, {l, l, l}, {0, 0, 0}, mass, 0, 1, seed);
}

template <class Pot>
void expect_matches_brute_force(const dpd::Particles& p0, const dpd::Domain& d, const Pot& pot, double skin) {
  dpd::Particles p = p0;
  dpd::PairList list;
  list.build(p, d, pot.cutoff(), skin, false);
  dpd::ForceBuffers buf;
  const auto sums = dpd::compute_pair_forces(dpd::PairPotential{pot}, list, p, nullptr, buf, 1);
  const auto ref = test::brute_force(p0, d, pot);
  double fscale = 0;
  for (std::size_t i = 0; i < p.size(); ++i) fscale = std::max({fscale, std::abs(ref.fx[i]), std::abs(ref.fy[i])});
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_NEAR(p.fx[i], ref.fx[i], 1e-12 * fscale) << "particle " << i;
    ASSERT_NEAR(p.fy[i], ref.fy[i], 1e-12 * fscale) << "particle " << i;
    ASSERT_NEAR(p.fz[i], ref.fz[i], 1e-12 * fscale) << "particle " << i;
  }
  EXPECT_NEAR(sums.energy, ref.energy, 1e-12 * std::abs(ref.energy));
  double vscale = std::abs(ref.virial[0]) + std::abs(ref.virial[1]) + std::abs(ref.virial[2]);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(sums.virial[k], ref.virial[k], 1e-12 * vscale) << "virial " << k;
}

TEST(DpdForces, SoftFluidMatchesBruteForcePeriodic) {
  const test::SoftFluid f;
  expect_matches_brute_force(fluid(400, 40.0, 3), cube(40.0), f.potential(), 2.0);
}

TEST(DpdForces, SmallBoxManyImagesMatchesBruteForce) {
  // Edge 1.5 rc: a particle meets two images of some neighbours (and of itself).
  const test::SoftFluid f;
  expect_matches_brute_force(fluid(30, 15.0, 5), cube(15.0), f.potential(), 1.0);
}

TEST(DpdForces, OpenAxesMatchBruteForce) {
  // Open x and z, periodic y; particles also outside the box along the open axes.
  dpd::Particles p = dpd::random_block(300, {60.0, 30.0, 50.0}, {-10.0, 0.0, -5.0}, 100.0, 0, 1, 9);
  expect_matches_brute_force(p, [] {
    dpd::Domain d = cube(30.0, {false, true, false});
    d.box.lx = 40.0;
    d.box.lz = 40.0;
    return d;
  }(), test::SoftFluid{}.potential(), 1.0);
}

TEST(DpdForces, MorseCrystalMatchesBruteForce) {
  dpd::Particles p = dpd::fcc_block({3, 3, 3}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  particles::RngStream rng(11, 0);
  for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += 0.3 * (rng.uniform() - 0.5), p.y[i] += 0.3 * rng.uniform();
  dpd::Domain d = cube(3 * test::kCoarseLattice);
  for (std::size_t i = 0; i < p.size(); ++i) p.x[i] = d.wrap(0, p.x[i]), p.y[i] = d.wrap(1, p.y[i]);
  expect_matches_brute_force(p, d, test::cu_meso_morse(), 1.0);
}

// -dU/dr from eval against central differences of the energy, for every potential.
template <class Pot>
void expect_force_is_minus_gradient(const Pot& pot, double r_lo) {
  const double h = 1e-6;
  for (double r = r_lo; r < pot.cutoff() - 2 * h; r += 0.0371 * pot.cutoff()) {
    double e, fr, ep, em, dummy;
    pot.eval(r * r, e, fr);
    pot.eval((r + h) * (r + h), ep, dummy);
    pot.eval((r - h) * (r - h), em, dummy);
    const double f = -(ep - em) / (2 * h);
    EXPECT_NEAR(fr * r, f, 1e-6 * (std::abs(f) + std::abs(e) / r + 1e-3)) << pot.name << " at r = " << r;
  }
  double e, fr;
  const double rc = pot.cutoff() * (1 - 1e-12);
  pot.eval(rc * rc, e, fr);
  EXPECT_NEAR(e, 0.0, 1e-9) << pot.name << ": the energy is shifted to zero at the cutoff";
}

TEST(DpdForces, ForceIsMinusEnergyGradient) {
  expect_force_is_minus_gradient(test::SoftFluid{}.potential(), 0.5);
  expect_force_is_minus_gradient(test::cu_meso_morse(), 3.5);
  dpd::NmPotential nm;
  nm.e0 = 2.0, nm.r0 = 5.1, nm.n = 9, nm.m = 6, nm.rc = 12.0;
  nm.update_offset();
  expect_force_is_minus_gradient(nm, 3.8);
  EXPECT_EQ(dpd::pair_potential_names(), (std::vector<std::string>{"dpd", "morse", "nm"}));
}

TEST(DpdForces, PairForcesSumToZeroWithDissipativeAndRandom) {
  const test::SoftFluid f;
  dpd::Particles p = fluid(500, 40.0, 21);
  dpd::maxwell_velocities(p, 300.0, 4);
  const dpd::Domain d = cube(40.0);
  dpd::PairList list;
  list.build(p, d, f.rc, 2.0, false);
  dpd::StochasticForces st;
  st.gamma = f.gamma(), st.temperature = 300, st.cutoff = f.rc, st.dt = 0.05, st.seed = 8, st.step = 3;
  dpd::ForceBuffers buf;
  dpd::compute_pair_forces(dpd::PairPotential{f.potential()}, list, p, &st, buf, 2);
  double sx = 0, sy = 0, sz = 0, mag = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    sx += p.fx[i], sy += p.fy[i], sz += p.fz[i];
    mag += std::abs(p.fx[i]) + std::abs(p.fy[i]) + std::abs(p.fz[i]);
  }
  EXPECT_GT(mag, 0.0);
  EXPECT_LT(std::abs(sx) + std::abs(sy) + std::abs(sz), 1e-13 * mag);
}

// Total momentum over a run of each integrator, relative to sum m |v|.
void expect_momentum_conserved(dpd::DpdParams par, int steps, double dt) {
  const test::SoftFluid f;
  dpd::Particles p = fluid(600, 42.0, 31, f.mass);
  dpd::maxwell_velocities(p, 300.0, 5);
  if (par.energy_conserving)
    for (auto& u : p.u) u = par.heat_capacity * 300.0;
  dpd::System s(p, cube(42.0), f.potential(), par, {.skin = 3.0, .threads = 2});
  const auto p0 = s.momentum();
  double scale = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    scale += p.mass[i] * std::sqrt(p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i] + p.vz[i] * p.vz[i]);
  s.advance(steps, dt);
  const auto p1 = s.momentum();
  EXPECT_GT(s.neighbor_builds(), 1);
  for (int k = 0; k < 3; ++k) EXPECT_LT(std::abs(p1[k] - p0[k]), 1e-12 * scale) << "component " << k;
}

TEST(DpdForces, MomentumConservedByVelocityVerletDpd) {
  const test::SoftFluid f;
  dpd::DpdParams par;
  par.integrator = dpd::Integrator::velocity_verlet;
  par.gamma = f.gamma(), par.cutoff = f.rc, par.temperature = 300, par.seed = 3;
  expect_momentum_conserved(par, 200, 0.02 * f.tau());
}

TEST(DpdForces, MomentumConservedByShardlowDpde) {
  const test::SoftFluid f;
  dpd::DpdParams par;
  par.energy_conserving = true;
  par.gamma = f.gamma(), par.cutoff = f.rc, par.heat_capacity = 10 * 8.617343e-5, par.seed = 3;
  expect_momentum_conserved(par, 200, 0.02 * f.tau());
}

}  // namespace
