// md_closure in 2-D (issue 14, dissertation sec. 7.2): zero stress at rest at 0 K, a
// sheared box against a directly sheared md::System (eq. 5.20 and the rotation it
// implies), energy consistency (eq. 7.11) to round-off per macro step, thread-count
// independence and checkpoint/resume bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "ms_test_util.hpp"

namespace {

using namespace mpmx;

app::MpmConfig impact_2d(double temperature, int steps, bool consistent = true) {
  return app::read_mpm_deck_text(test::flyer_2d_deck(temperature, steps, consistent), "md_closure_2d");
}

md::Mat3 gradient(double gxy, double gyx) {
  md::Mat3 g{};
  g[1] = gxy, g[3] = gyx;
  return g;
}

}  // namespace

TEST(MdClosure2d, RestingCrystalAtZeroKelvinHasNoStress) {
  auto c = impact_2d(0.0, 1);
  auto md_cfg = test::closure_config(c);
  md_cfg.threads = 1;
  multiscale::MdClosure<2> m(md_cfg);
  mpm::Particles<2> p;
  p.resize(2);
  p.mass = {1.0, 1.0};
  p.volume = p.volume0 = {1.0, 1.0};
  m.initialize(mpm::points(p));
  m.update_stress(mpm::points(p), 0.1);
  for (int k = 0; k < 4; ++k)
    for (std::size_t q = 0; q < 2; ++q) EXPECT_LT(std::abs(p.stress[k][q]), 1e-9) << k;
  EXPECT_EQ(m.atom_steps(), 2 * 108 * 100);
}

// An upper-triangular shear is what the box does itself; a lower-triangular one becomes
// the upper one (eq. 5.20) with the rotation carried by the point: the same box stress,
// turned by R.
TEST(MdClosure2d, ShearedBoxMatchesADirectlyShearedSystem) {
  auto c = impact_2d(0.0, 1, false);
  auto md_cfg = test::closure_config(c);
  md_cfg.threads = 1;
  const double rate = 0.02;  // 1/ps
  md::System direct(md::fcc(3, 3, 3, multiscale::MdClosure<2>(md_cfg).equilibrium().lattice_constant),
                    md::Potential(md_cfg.potential));
  direct.advance(100, gradient(rate, 0.0), 0.001);
  for (const bool lower : {false, true}) {
    multiscale::MdClosure<2> m(md_cfg);
    mpm::Particles<2> p;
    p.resize(1);
    p.mass = {1.0};
    p.volume = p.volume0 = {1.0};
    m.initialize(mpm::points(p));
    (lower ? p.grad_v[2] : p.grad_v[1]) = {rate};
    m.update_stress(mpm::points(p), 0.1);
    ASSERT_EQ(m.box(0)->atoms().size(), 108u);
    const md::Mat3 s = direct.stress_gpa();
    ASSERT_GT(std::abs(s[1]), 0.1);  // a real shear stress, GPa
    if (!lower) {
      EXPECT_EQ(p.stress[1][0], s[1]);  // bit for bit: the same box
      EXPECT_EQ(p.stress[0][0], s[0]);
      continue;
    }
    // The spin difference W - W' = [[0, -rate], [rate, 0]] over 0.1 ps: R turns by
    // 0.1 rate about z; sigma = R s R^T.
    const double th = rate * 0.1, cs = std::cos(th), sn = std::sin(th);
    const double sxx = cs * cs * s[0] - 2 * sn * cs * s[1] + sn * sn * s[4];
    const double sxy = sn * cs * (s[0] - s[4]) + (cs * cs - sn * sn) * s[1];
    EXPECT_NEAR(p.stress[0][0], sxx, 1e-9 * std::abs(s[1]));
    EXPECT_NEAR(p.stress[1][0], sxy, 1e-9 * std::abs(s[1]));
    EXPECT_EQ(p.stress[1][0], p.stress[2][0]);
  }
}

// Eq. 7.11: after each macro step the box's energy (potential plus thermal kinetic)
// has changed by exactly the continuum's work V sigma : D dt, sigma the mean of the box's
// samples at the step's two ends.
TEST(MdClosure2d, EnergyConsistencyHoldsToRoundOffEachMacroStep) {
  auto c = impact_2d(100.0, 1, true);
  auto md_cfg = test::closure_config(c);
  md_cfg.threads = 1;
  multiscale::MdClosure<2> m(md_cfg);
  mpm::Particles<2> p;
  p.resize(1);
  p.mass = {1.0};
  p.volume = p.volume0 = {1.0};
  m.initialize(mpm::points(p));
  p.grad_v[0] = {-0.05};  // compression with shear (upper triangular: the point's frame is the box's)
  p.grad_v[1] = {0.03};
  for (int step = 0; step < 3; ++step) {
    const md::System before = *m.box(0);
    // The stress the continuum saw (GPa in these units) on the rate of deformation.
    auto power = [&] { return p.stress[0][0] * -0.05 + (p.stress[1][0] + p.stress[2][0]) * 0.5 * 0.03; };
    const double power_before = power();
    m.update_stress(mpm::points(p), 0.1);
    const md::System& after = *m.box(0);
    const double work = 0.5 * (before.box().volume() + after.box().volume()) * 0.5 * (power_before + power()) *
                        0.1 / 160.21766208;
    const double change = after.potential_energy() + after.thermal_kinetic_energy() - before.potential_energy() -
                          before.thermal_kinetic_energy();
    EXPECT_NEAR(change, work, 1e-9 * (std::abs(after.potential_energy()) + 1.0)) << step;
    EXPECT_GT(std::abs(work), 1e-3);  // eV: a real exchange
    // The closure's tally of list builds is the box's own.
    EXPECT_EQ(m.neighbor_builds(), m.box(0)->neighbor_builds()) << step;
  }
  EXPECT_EQ(m.energy_shortfall_ev(), 0.0);
  EXPECT_GE(m.neighbor_builds(), 1);
}

TEST(MdClosure2d, SameParticlesOnOneAndTwoThreadsAndResumedBitForBit) {
  const auto c = impact_2d(50.0, 4);
  const auto [one, two] = test::same_on_one_and_two_threads<2>(c, false);  // the boxes take the threads
  // One box per point would run 8 x 108 atoms for 400 relaxation and 20 MD steps; the
  // eight points start alike, so they share boxes until their histories part.
  EXPECT_EQ(std::get<std::int64_t>(test::closure_figure(one, "md.atom_steps_unshared")), 8 * 108 * (400 + 20));
  EXPECT_LT(one.md_atom_steps, 8 * 108 * (400 + 20));
  EXPECT_EQ(one.md_atom_steps, two.md_atom_steps);
  EXPECT_LT(one.momentum_error(), 1e-12 * one.momentum_scale);
  // The flyer is pushed back by the target.
  double v_flyer = 0.0;
  for (std::size_t q = 0; q < one.state.particles.size(); ++q)
    if (one.state.particles.x[0][q] < 0.9) v_flyer = std::max(v_flyer, one.state.particles.v[0][q]);
  EXPECT_LT(v_flyer, 0.5);

  app::RunOptions o = test::stopping_run("md_closure_2d_parts", 2, 2);
  const auto first = app::run_mpm_dim<2>(c, o);
  EXPECT_TRUE(first.interrupted);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm_dim<2>(c, o);
  EXPECT_EQ(rest.steps, 4);
  test::expect_same_particles(two.state.particles, rest.state.particles);
}

// A resumed 2-D DDMP-MD run equals the uninterrupted one to the bit from a checkpoint at
// every step, the first (right after the boxes' relaxation) included, with the boxes
// shared, split and audited along the way (50 K: thermal boxes, eq. 7.11 on).
TEST(MdClosure2d, ResumedFromEveryStepBitForBit) {
  const int steps = 8;
  const auto c = impact_2d(50.0, steps);
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 2;
  const auto whole = app::run_mpm_dim<2>(c, o);
  ASSERT_EQ(whole.steps, steps);
  for (int k = 1; k < steps; ++k) {
    o.out_dir = test::scratch_dir("md_closure_2d_every_step");
    o.resume = false;
    o.stop_after = k;
    const auto first = app::run_mpm_dim<2>(c, o);
    ASSERT_TRUE(first.interrupted) << k;
    o.stop_after = 0;
    o.resume = true;
    const auto rest = app::run_mpm_dim<2>(c, o);
    EXPECT_EQ(rest.steps, steps) << k;
    EXPECT_EQ(rest.md_atom_steps, whole.md_atom_steps) << k;
    test::expect_same_particles(whole.state.particles, rest.state.particles);
    EXPECT_EQ(rest.state.particles.stress_zz, whole.state.particles.stress_zz) << k;
  }
}
