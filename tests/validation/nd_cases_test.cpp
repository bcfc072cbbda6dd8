// ctest-label: slow
// The 2-D and 3-D cases of the validation catalog that run in seconds: N3 (two elastic
// disks), N5 (two spheres), N6 (copper planar impact, Mie-Gruneisen with the tensor
// viscosity), N7 (a spinning disk). Where a catalog target is not met yet the test holds
// the measured figure as a regression bound and docs/validation.md says why.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mpm/mpm_test_util.hpp"
#include "mpmx/app/mpm/convergence.hpp"
#include "mpmx/app/mpm/setup.hpp"

using namespace mpmx;

namespace {

template <int Dim>
double total_energy(const app::RunResultOf<Dim>& r) { return r.kinetic_final + r.stored_final; }

// Mean velocity along (1, 1) of the disk that started at x + y < 0.
template <int Dim>
double approach_speed(const mpm::Particles<Dim>& p, const std::vector<bool>& first) {
  double m = 0.0, mv = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (first[q]) {
      m += p.mass[q];
      mv += p.mass[q] * (p.v[0][q] + p.v[1][q]) / std::sqrt(2.0);
    }
  return mv / m;
}

}  // namespace

TEST(N3, TwoDisksKeepMomentumRoundOffAndRebound) {
  double mpm_drift = 1.0;
  for (const std::string scheme : {"mpm", "ugimp", "cpgimp", "cpdi", "ddmp", "ddmp_subpoints"}) {
    const auto c = test::deck(test::example("N3_two_disks_" + scheme + ".toml"));
    const auto r = test::run_dim<2>(c);
    ASSERT_EQ(r.steps, 350) << scheme;
    EXPECT_NEAR(r.kinetic_initial, 2.6, 0.1) << scheme;  // E0 = 2.600 at the peer's point count
    EXPECT_LT(r.momentum_error(), 1e-12 * r.momentum_scale) << scheme;
    // The disks rebound: the first disk moves back along (1, 1).
    std::vector<bool> first(r.state.particles.size());
    const auto s0 = app::make_state<2>(c);
    for (std::size_t q = 0; q < first.size(); ++q) first[q] = s0.particles.x[0][q] + s0.particles.x[1][q] < 0.0;
    EXPECT_GT(approach_speed(s0.particles, first), 0.1);
    EXPECT_LT(approach_speed(r.state.particles, first), -0.05) << scheme;
    // Energy after separation (the decks' MUSL update): within the catalog's 0.8% of E0 at
    // t = 3.5 for every scheme, sub-points at least as close as mpm (docs/validation.md, N3).
    const double e0 = r.kinetic_initial;
    const double drift = std::abs(total_energy(r) - e0) / e0;
    EXPECT_LT(drift, 0.008) << scheme;
    if (scheme == "mpm") mpm_drift = drift;
    if (scheme == "ddmp_subpoints") {
      EXPECT_LE(drift, mpm_drift);
    }
  }
}

// N5 at the catalog's 20^3 cells (MUSL): mpm within 0.8% of E0 at t = 3.5 (measured
// -0.54%); ddmp -1.54%, held as a bound (docs/validation.md).
TEST(N5, TwoSpheresKeepMomentumRoundOffAndRebound) {
  for (const auto& [scheme, bound] : {std::pair{"mpm", 0.008}, {"ddmp", 0.02}}) {
    const auto c = test::deck(test::example(std::string("N5_two_spheres_") + scheme + ".toml"));
    ASSERT_EQ(c.cells_all[0], 20);
    const auto r = test::run_dim<3>(c);
    EXPECT_LT(r.momentum_error(), 1e-12 * r.momentum_scale) << scheme;
    std::vector<bool> first(r.state.particles.size());
    const auto s0 = app::make_state<3>(c);
    for (std::size_t q = 0; q < first.size(); ++q) first[q] = s0.particles.x[0][q] + s0.particles.x[1][q] < 0.0;
    EXPECT_LT(approach_speed(r.state.particles, first), -0.05) << scheme;
    const double e0 = r.kinetic_initial;
    EXPECT_LT(std::abs(total_energy(r) - e0) / e0, bound) << scheme;
  }
}

// N5's ddmp energy on the refined grid (N3's "and refined"): DDMP's smoothing loses
// energy in proportion to the cell (-1.54% at 20^3, -1.09% at 30^3, -0.68% at 40^3 at
// t = 3.5); at 40^3 it is within N3's 0.8%. dt scaled with the cell.
TEST(N5, DdmpEnergyWithinN3sBoundOnTheRefinedGrid) {
  const auto c = test::deck_with(test::example("N5_two_spheres_ddmp.toml"), [](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", toml::array{40, 40, 40});
    t["time"].as_table()->insert_or_assign("dt", 0.005);
  });
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 2;
  const auto r = app::run_mpm_dim<3>(c, o);
  EXPECT_LT(r.momentum_error(), 1e-12 * r.momentum_scale);
  const double e0 = r.kinetic_initial;
  EXPECT_LT(std::abs(total_energy(r) - e0) / e0, 0.008);
  EXPECT_GT(std::abs(total_energy(r) - e0) / e0, 0.002);  // a real loss, shrinking with the cell
}

// N6: shock speed from the front's positions at the two records, stress on the plateau
// behind it, against the Hugoniot: Us = c0 + s up = 5.8025 km/s, sigma_xx = -(rho0 Us up
// + 2/3 Y) at up = 1.25 km/s.
TEST(N6, CopperPlanarImpactFollowsTheHugoniot) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  // The front (rightmost target point moving faster than up / 2) at t = 0.6 and 1.2 us.
  auto front_at = [&](double t, double& sxx) {
    const auto ct = test::deck_with(test::example("N6_copper_planar_impact.toml"), [&](toml::table& d) {
      d["time"].as_table()->insert_or_assign("end", t);
      d["output"].as_table()->insert_or_assign("times", toml::array{t});
    });
    const auto r = app::run_mpm_dim<2>(ct, o);
    const auto& p = r.state.particles;
    double front = 0.0;
    for (std::size_t q = 0; q < p.size(); ++q)
      if (p.x[0][q] > 2.5 && p.v[0][q] > 0.625) front = std::max(front, p.x[0][q]);
    double s = 0.0;
    int n = 0;
    for (std::size_t q = 0; q < p.size(); ++q)
      if (p.x[0][q] > front - 1.2 && p.x[0][q] < front - 0.4) s += p.stress[0][q], ++n;
    sxx = s / n;
    return front;
  };
  double s1 = 0.0, s2 = 0.0;
  const double x1 = front_at(0.6, s1), x2 = front_at(1.2, s2);
  const double us = (x2 - x1) / 0.6, up = 1.25, rho0 = 8.93, Y = 0.12;
  const double us_ref = 3.94 + 1.49 * up;
  EXPECT_NEAR(us, us_ref, 0.02 * us_ref);
  const double sxx_ref = -(rho0 * us_ref * up + 2.0 / 3.0 * Y);
  EXPECT_NEAR(s1, sxx_ref, 0.03 * std::abs(sxx_ref));
}

// Bodies with their own laws: an aluminium flyer on the copper target. The shock in the
// copper follows the copper Hugoniot at the particle velocity where the two Hugoniots
// meet (impedance matching), u = 0.780 km/s, Us = 5.10 km/s; the flyer keeps its own
// (lighter) law, so a run with both bodies of copper would give u = 1.25 instead.
TEST(N6, AluminiumFlyerOnCopperMatchesImpedances) {
  const double v = 2.5, rho_cu = 8.93, c_cu = 3.94, s_cu = 1.49, rho_al = 2.70, c_al = 5.35, s_al = 1.34;
  double a = 0.0, b = v;  // bisection on the pressure balance
  for (int k = 0; k < 100; ++k) {
    const double u = 0.5 * (a + b);
    const double f = rho_cu * (c_cu + s_cu * u) * u - rho_al * (c_al + s_al * (v - u)) * (v - u);
    (f > 0 ? b : a) = u;
  }
  const double up = 0.5 * (a + b), us_ref = c_cu + s_cu * up;
  ASSERT_NEAR(up, 0.780, 0.001);
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  auto front_at = [&](double t, double& sxx, double& u_behind, std::string& law) {
    const auto ct = test::deck_with(test::example("N6_aluminium_on_copper.toml"), [&](toml::table& d) {
      d["time"].as_table()->insert_or_assign("end", t);
      d["output"].as_table()->insert_or_assign("times", toml::array{t});
    });
    const auto r = app::run_mpm_dim<2>(ct, o);
    law = r.state.material->name();
    const auto& p = r.state.particles;
    double front = 0.0;
    for (std::size_t q = 0; q < p.size(); ++q)
      if (p.x[0][q] > 2.5 && p.v[0][q] > 0.5 * up) front = std::max(front, p.x[0][q]);
    double s = 0.0, w = 0.0;
    int n = 0;
    for (std::size_t q = 0; q < p.size(); ++q)
      if (p.x[0][q] > front - 1.2 && p.x[0][q] < front - 0.4) s += p.stress[0][q], w += p.v[0][q], ++n;
    sxx = s / n, u_behind = w / n;
    return front;
  };
  double s1 = 0.0, s2 = 0.0, u1 = 0.0, u2 = 0.0;
  std::string law;
  const double x1 = front_at(0.6, s1, u1, law), x2 = front_at(1.2, s2, u2, law);
  EXPECT_EQ(law, "mie_gruneisen+mie_gruneisen");
  EXPECT_NEAR(u1, up, 0.03 * up);
  EXPECT_NEAR((x2 - x1) / 0.6, us_ref, 0.02 * us_ref);
  const double sxx_ref = -(rho_cu * us_ref * up + 2.0 / 3.0 * 0.12);
  EXPECT_NEAR(s1, sxx_ref, 0.03 * std::abs(sxx_ref));
}

// N2: the shock tube with its partition at 30 degrees to the grid against the 1-D exact
// solution along the normal, beside the same run with the partition along a grid line.
TEST(N2, RotatedShockTubeIsAsAccurateAsTheAlignedOne) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  for (const std::string scheme : {"cpdi", "ddmp_subpoints"}) {
    const auto rotated = test::deck(test::example("N2_rotated_shock_tube_" + scheme + ".toml"));
    ASSERT_NEAR(rotated.pressure.normal[1], 0.5, 1e-15);
    const auto aligned = test::deck_with(test::example("N2_rotated_shock_tube_" + scheme + ".toml"), [](toml::table& t) {
      t["initial"].as_table()->get("pressure")->as_table()->insert_or_assign("normal", toml::array{1.0, 0.0});
    });
    const auto r = app::run_mpm_dim<2>(rotated, o);
    const auto a = app::run_mpm_dim<2>(aligned, o);
    const double er = r.errors.at("pressure").l1, ea = a.errors.at("pressure").l1;
    EXPECT_GT(ea, 0.0) << scheme;
    EXPECT_LT(ea, 0.2) << scheme;  // the shock and the fan are there, in the right places
    EXPECT_LE(er, 1.5 * ea) << scheme << ": rotated " << er << ", aligned " << ea;
  }
}

// N4: the manufactured axis-aligned displacement, the deck's study cut to 3 grids (16^2
// to 64^2 cells): the observed L2 order of the displacement is at least 1.8 for cpgimp
// and cpdi and 1.5 for ddmp_subpoints (the decks' 4 grids: docs/validation.md).
TEST(N4, ManufacturedSolutionConvergesAtTheCatalogOrder) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  for (const auto& [scheme, least] : {std::pair{"cpgimp", 1.8}, {"cpdi", 1.8}, {"ddmp_subpoints", 1.5}}) {
    const auto c = test::deck_with(test::example(std::string("N4_manufactured_") + scheme + ".toml"),
                                   [](toml::table& t) { t["convergence"].as_table()->insert_or_assign("levels", 3); });
    const auto study = app::run_convergence(c, o);
    ASSERT_EQ(study.levels.size(), 3u) << scheme;
    const double order = study.order_l2.at("displacement");
    EXPECT_GE(order, least) << scheme;
    EXPECT_LT(study.levels.back().run.errors.at("displacement").l2, 0.01) << scheme;  // of the amplitude
  }
}

// N7: a disk set spinning rigidly. Objectivity itself is tested at the material level
// (tests/material/jaumann_test.cpp: exactly no stress from a rigid spin). A free disk
// spinning is not stress-free: it needs the radial tension that turns its points, of
// order (3 + nu)/8 rho (omega R)^2 at the centre, and starting unstressed it oscillates
// about that; the catalog's bound of 1e-8 rho (omega R)^2 conflicts with this
// (docs/validation.md, N7). Held here: the stress stays at that physical scale and the
// angular momentum is kept.
TEST(N7, SpinningDiskStressStaysAtTheCentripetalScale) {
  const auto c = test::deck(test::example("N7_rigid_rotation.toml"));
  const auto r = test::run_dim<2>(c);
  const auto& p = r.state.particles;
  const double scale = 1000.0 * 0.3 * 0.3;  // rho (omega R)^2
  double smax = 0.0, L0 = 0.0, L1 = 0.0;
  const auto s0 = app::make_state<2>(c);
  for (std::size_t q = 0; q < p.size(); ++q) {
    for (int k = 0; k < 4; ++k) smax = std::max(smax, std::abs(p.stress[k][q]));
    L0 += p.mass[q] * (s0.particles.x[0][q] * s0.particles.v[1][q] - s0.particles.x[1][q] * s0.particles.v[0][q]);
    L1 += p.mass[q] * (p.x[0][q] * p.v[1][q] - p.x[1][q] * p.v[0][q]);
  }
  EXPECT_GT(smax, 0.1 * scale);
  EXPECT_LT(smax, 2.0 * scale);
  EXPECT_NEAR(L1, L0, 0.02 * std::abs(L0));
}

// Results do not depend on the thread count: p2g scatters by slabs in a fixed order.
TEST(N5, SameResultOnOneAndTwoThreads) {
  const auto c = test::deck_with(test::example("N5_two_spheres_ddmp.toml"), [](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", toml::array{26, 26, 26});
    t["time"].as_table()->insert_or_assign("dt", 0.02);
    t["time"].as_table()->insert_or_assign("end", 0.4);
  });
  const auto [one, two] = test::same_on_one_and_two_threads<3>(c);
  EXPECT_GE(one.state.particles.size(), 8192u);
}

// The same in 2-D through every threaded piece of the step: DDMP's grid operator, MUSL's
// re-mapped gradient, the small-mass maps, the solve's face tallies, the energy sums, and
// (N6) the Mie-Gruneisen update, its viscous heat and the tensor viscosity.
TEST(N3N6, SameResultOnOneAndTwoThreadsIn2D) {
  for (const char* name : {"N3_two_disks_ddmp.toml", "N6_copper_planar_impact.toml"}) {
    SCOPED_TRACE(name);
    const bool disks = std::string(name).starts_with("N3");
    const auto c = test::deck_with(test::example(name), [&](toml::table& t) {
      if (disks) {
        t["grid"].as_table()->insert_or_assign("cells", toml::array{120, 120});
        t["time"].as_table()->insert_or_assign("dt", 0.0025);
      } else {  // twice as many rows of points across
        t["grid"].as_table()->insert_or_assign("cells", toml::array{280, 8});
      }
      t["time"].as_table()->insert_or_assign("end", 0.3);
      if (!disks) t["output"].as_table()->insert_or_assign("times", toml::array{0.3});
    });
    test::same_on_one_and_two_threads<2>(c);
  }
}
