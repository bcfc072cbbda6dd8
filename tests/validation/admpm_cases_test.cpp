// ctest-label: validation
// ADMPM's test problems A1-A4 (VALIDATION.md) against their analytic solutions.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

// The largest relative L2 error of `field` over its compared times, and per time.
double l2_at(const app::RunResult& r, const std::string& field) { return r.errors.at(field).l2; }

}  // namespace

// A1, static particles: v and strain within 1% at t = 0.3 and 1.2; v within 1% at 2.1.
// At t = 2.1 the strain is passing through zero (sin(2.1 pi) = 0.31) and the phase
// error of the particle-to-node re-map, -(k dx)^2/8, shows as 1.1%: below 1.2% asserted,
// and it converges at second order (next test).
TEST(A1, StandingWaveStatic) {
  const auto c = test::deck(test::example("A1_standing_wave_static.toml"));
  const auto r = test::run(c);
  EXPECT_LT(l2_at(r, "velocity"), 0.01);
  EXPECT_LT(r.errors.at("strain").l2, 0.012);
}

TEST(A1, StandingWaveStaticConvergesSecondOrder) {
  auto at = [](int cells) {
    const auto c = test::deck_with(test::example("A1_standing_wave_static.toml"), [&](toml::table& t) {
      t["grid"].as_table()->insert_or_assign("cells", cells);
    });
    return test::run(c).errors.at("strain").l2;
  };
  const double e50 = at(50), e100 = at(100);
  EXPECT_GT(e50 / e100, 3.5);
  EXPECT_LT(e100, 0.003);
}

TEST(A1, StandingWaveMoving) {
  const auto c = test::deck(test::example("A1_standing_wave_moving.toml"));
  const auto r = test::run(c);
  EXPECT_LT(l2_at(r, "velocity"), 0.01);
  EXPECT_LT(l2_at(r, "strain"), 0.0125);  // 0.99%, 0.78%, 1.18% at t = 0.3, 1.2, 2.1
}

// A2: v and strain against eqs. 8.21-8.22 at t = 0.8, 1.2; total energy against eq. 8.27.
// The seed's 101 nodes give L2 3.5%, above the catalogue's 2%: the error sits at the
// kink of the analytic front (docs/validation.md); L1 is 2.0-2.6%.
TEST(A2, WaveReflection) {
  const auto c = test::deck(test::example("A2_wave_reflection_moving.toml"));
  const auto r = test::run(c);
  EXPECT_LT(r.errors.at("velocity").l1, 0.025);
  EXPECT_LT(r.errors.at("strain").l1, 0.03);
  EXPECT_LT(l2_at(r, "velocity"), 0.04);
  EXPECT_LT(l2_at(r, "strain"), 0.04);
  EXPECT_LT(r.errors.at("energy").l1, 0.02);  // max |E - E_ref| / max E_ref for t <= 2
}

// A2 with static particles (a discretisation of the linear theory of eqs. 8.21-8.22, no
// geometric terms) on finer grids: the catalogue's 2% is met from 201 nodes on (1.7%),
// and 401 nodes halve it again (0.83%).
TEST(A2, StaticParticlesConverge) {
  auto at = [](int cells) {
    const auto c = test::deck_with(test::example("A2_wave_reflection_moving.toml"), [&](toml::table& t) {
      t["grid"].as_table()->insert_or_assign("cells", cells);
      t["particles"].as_table()->insert_or_assign("move", false);
      t["time"].as_table()->insert_or_assign("end", 1.2);
      t["output"].as_table()->insert_or_assign("times", toml::array{1.2});
    });
    return test::run(c);
  };
  const auto r200 = at(200), r400 = at(400);
  EXPECT_LT(l2_at(r200, "velocity"), 0.02);
  EXPECT_LT(l2_at(r200, "strain"), 0.02);
  EXPECT_LT(l2_at(r400, "velocity"), 0.01);
  EXPECT_LT(l2_at(r400, "strain"), 0.01);
}

// Where the gradient varies inside a cell (DDMP here), moving particles weigh the stress
// at their current positions with their initial volumes, terms of order v0/c that the
// linear theory of eqs. 8.21-8.22 leaves out: on 401 nodes (no cell-crossing noise) the
// error stays at 5.1% with the seed's amplitude 0.01, while at amplitude 0.001 it is the
// static particles' 1.2-1.3%.
TEST(A2, MovingParticlesDifferFromLinearTheoryByAmplitude) {
  auto at = [](double amplitude, bool move) {
    const auto c = test::deck_with(test::example("A2_wave_reflection_moving.toml"), [&](toml::table& t) {
      t["grid"].as_table()->insert_or_assign("cells", 400);
      t["scheme"].as_table()->insert_or_assign("name", "ddmp");
      t["particles"].as_table()->insert_or_assign("move", move);
      t["boundary"]["right"].as_table()->insert_or_assign("amplitude", amplitude);
      t["time"].as_table()->insert_or_assign("end", 1.2);
      t["output"].as_table()->insert_or_assign("times", toml::array{1.2});
    });
    return l2_at(test::run(c), "velocity");
  };
  const double large = at(0.01, true), small = at(0.001, true), fixed = at(0.001, false);
  EXPECT_GT(large, 0.04);
  EXPECT_LT(small, 0.015);
  EXPECT_LT(std::abs(small - fixed), 0.2 * fixed);
}

// A4: ideal gas driven at the right end, eq. 7.8. 76 nodes: L1 3.4%, L2 5.4% (front kink).
TEST(A4, IdealGasWave) {
  const auto c = test::deck(test::example("A4_gas_wave.toml"));
  const auto r = test::run(c);
  EXPECT_LT(r.errors.at("velocity").l1, 0.04);
  EXPECT_LT(l2_at(r, "velocity"), 0.06);
}

// A4 with static particles on 301 nodes meets the catalogue's 2% (1.90%): the 76-node
// miss is resolution. Moving particles cannot be refined so: from 151 nodes on they cross
// cell faces, and with the background pressure p0 = 1, 100 times the wave's, the
// original MPM's cell-crossing force error swamps the wave (dissertation sec. 4.1).
TEST(A4, StaticParticlesMeetTheTargetOnAFinerGrid) {
  const auto c = test::deck_with(test::example("A4_gas_wave.toml"), [](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", 300);
    t["particles"].as_table()->insert_or_assign("move", false);
  });
  const auto r = test::run(c);
  EXPECT_LT(l2_at(r, "velocity"), 0.02);
}
