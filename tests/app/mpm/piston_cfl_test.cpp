// ctest-cost: 1
// dt = "cfl" with a fast piston: each step counts the piston's speed among the flow's
// (|v| + c), so that the Courant number of every step stays at the deck's cfl (and well
// inside 1 with the speeds the step gave the points); the first step is the one `check`
// states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "mpm_deck_test_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/state_checks.hpp"
#include "mpmx/mpm/step_limit.hpp"
#include "mpmx/mpm/step.hpp"
#include "multiscale/ms_test_util.hpp"

namespace {

using namespace mpmx;

// A copper-like bar at rest, 40 cells along x, hit by a piston at 10 km/s.
const char* kPiston2d = R"(
[case]
id = "fast_piston"
units = "nm_ps_GPa"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [10.0, 0.25]
cells = [40, 1]
[particles]
per_cell = [2, 2]
[scheme]
name = "cpdi"
[material]
model = "linear_elastic"
youngs_modulus = 130.0
poisson_ratio = 0.34
density = 8.96
[viscosity]
linear = 0.5
[boundary]
x_lower = { type = "piston", velocity = 10.0 }
y_lower = { type = "roller" }
y_upper = { type = "roller" }
[time]
dt = "cfl"
cfl = 0.5
end = 0.1
)";

// The Courant number of a step of h from or to the state `s`: h x max (c + |v|) / dx, the
// piston's speed `wall` among the speeds (the points beside it take it in the step).
template <int Dim>
double courant(const mpm::State<Dim>& s, double h, double wall) {
  const auto view = mpm::points(s.particles);
  double fastest = 0, loudest = 0, dx = s.grid.dx[0];
  for (int d = 1; d < Dim; ++d) dx = std::min(dx, s.grid.dx[d]);
  for (std::size_t q = 0; q < s.particles.size(); ++q) {
    double v2 = 0;
    for (int a = 0; a < Dim; ++a) v2 += s.particles.v[a][q] * s.particles.v[a][q];
    const double c = s.material->sound_speed(view, q);
    fastest = std::max(fastest, c + std::sqrt(v2));
    loudest = std::max(loudest, c);
  }
  return h * std::max(fastest, loudest + wall) / dx;
}

}  // namespace

TEST(PistonCfl, EveryStepsCourantNumberStaysAtTheDecksCfl) {
  const auto c = app::read_mpm_deck_text(kPiston2d, "fast_piston.toml");
  ASSERT_TRUE(c.cfl_dt);
  auto s = app::make_state<2>(c, true, 1);
  double worst = 0, worst_after = 0, first = 0;
  int steps = 0;
  while (s.time < c.end && steps < 1000) {
    const double h = mpm::stable_dt(s, c.cfl);
    if (steps == 0) first = h;
    worst = std::max(worst, courant(s, h, 10.0));
    mpm::step(s, h);  // advances s.time and s.step
    ++steps;
    worst_after = std::max(worst_after, courant(s, h, 0.0));
  }
  EXPECT_GT(steps, 10);
  // Taken from the material at rest (c = 4.7 km/s) the first step's Courant number, the
  // piston's 10 km/s among the speeds, was 0.5 (c + 10) / c = 1.56.
  EXPECT_LE(worst, c.cfl * (1 + 1e-12)) << steps << " steps";
  // With the speeds each step gave the points (past the piston's where the shock rings),
  // it stays well inside 1 (it was 1.3 at the first step).
  EXPECT_LT(worst_after, 0.7);
  // `check`'s first step (what its step count is from) is the run's.
  EXPECT_NEAR(first, c.dt, 1e-12 * c.dt);
}

// A piston whose table speeds up within a step: the step counts its speed at the step's
// end, not only at its start.
TEST(PistonCfl, ATableRisingWithinTheStepCountsItsEnd) {
  const std::string deck = mpmx::test::replace(kPiston2d, "velocity = 10.0 }",
                                               "times = [0.0, 0.001], velocity = [0.0, 10.0] }");
  const auto c = app::read_mpm_deck_text(deck, "ramp.toml");
  auto s = app::make_state<2>(c, true, 1);
  const double h = mpm::stable_dt(s, c.cfl);
  const double c0 = s.material->sound_speed(mpm::points(s.particles), 0);
  EXPECT_NEAR(h, c.cfl * s.grid.dx[1] / (c0 + 10.0), 1e-9 * h);  // the table's 10 km/s reached within h
}

// The x-t table of a dt = "cfl" run takes a row at each 1/400 of the run's time (and at
// the start), however many steps the state makes: not every N steps with N estimated
// from the first step.
TEST(PistonCfl, XtRowsFollowTheRunsTimeNotItsFirstStep) {
  std::string deck = mpmx::test::replace(kPiston2d, "cells = [40, 1]", "cells = [200, 1]");
  deck = mpmx::test::replace(deck, "upper = [10.0, 0.25]", "upper = [10.0, 0.05]");
  deck = mpmx::test::replace(deck, "velocity = 10.0 }", "velocity = 0.1 }");
  deck = mpmx::test::replace(deck, "end = 0.1", "end = 3.5");
  const auto c = app::read_mpm_deck_text(deck, "slow_piston.toml");
  ASSERT_TRUE(c.write_xt);
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("piston_cfl_xt");
  const auto r = app::run_mpm_dim<2>(c, o);
  ASSERT_GT(r.steps, 500);  // more steps than rows: each row is a time's, not a step's
  std::ifstream in(o.out_dir + "/xt_sigma_xx.csv");
  std::string line;
  std::getline(in, line);  // the header
  std::vector<double> t;
  while (std::getline(in, line)) t.push_back(std::stod(line.substr(0, line.find(','))));
  ASSERT_EQ(t.size(), 401u);
  EXPECT_EQ(t.front(), 0.0);
  EXPECT_DOUBLE_EQ(t.back(), 3.5);
  // Each row at the first step at or past its multiple of 3.5 / 400, within a step.
  const double step = 3.5 / static_cast<double>(r.steps) * 2.0;
  for (std::size_t k = 1; k < t.size(); ++k) {
    EXPECT_GE(t[k], k * 3.5 / 400.0 * (1 - 1e-9)) << k;
    EXPECT_LT(t[k] - k * 3.5 / 400.0, step) << k;
  }
}
