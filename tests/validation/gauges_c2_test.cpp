// ctest-label: validation
// ctest-cost: 30
// C2 (VALIDATION.md): gauges in a symmetric Al plate impact at 1 km/s. The Lagrangian
// gauge in the target records u_p = 0.5 km/s and sigma_xx = rho0 Us u_p + 2/3 Y after
// the shock passes; the free-surface velocity of the target's rear face jumps to 2 u_p.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

// The mean of column `c` over the rows with t0 <= time <= t1.
double mean(const app::GaugeTrace& g, const std::string& c, double t0, double t1) {
  const int k = g.column(c), t = g.column("time");
  EXPECT_GE(k, 0) << c;
  double s = 0.0;
  int n = 0;
  for (const auto& row : g.rows)
    if (row[t] >= t0 && row[t] <= t1) s += row[k], ++n;
  EXPECT_GT(n, 10);
  return s / n;
}

const app::GaugeTrace& trace(const std::vector<app::GaugeTrace>& all, const std::string& name) {
  for (const auto& g : all)
    if (g.name == name) return g;
  ADD_FAILURE() << "no gauge " << name;
  return all.front();
}

}  // namespace

TEST(C2, PlateImpactGaugesRecordTheHugoniotState) {
  const auto c = test::deck(test::example("C2_plate_impact_gauges.toml"));
  const auto r = test::run_dim<2>(c);
  ASSERT_EQ(r.gauges.size(), 2u);
  const double rho0 = 2.703, c0 = 5.35, s = 1.34, Y = 0.29, up = 0.5;
  const double Us = c0 + s * up;                        // 6.02 km/s
  const double sigma = rho0 * Us * up + 2.0 / 3.0 * Y;  // 8.14 + 0.19 GPa
  // 1.5 nm into the target: the shock passes at 0.25 ps; the release from the flyer's
  // rear face arrives near 1 ps.
  const auto& mid = trace(r.gauges, "target_mid");
  EXPECT_NEAR(mean(mid, "vx", 0.4, 0.9), up, 0.02 * up);
  EXPECT_NEAR(mean(mid, "sigma_xx", 0.4, 0.9), -sigma, 0.02 * sigma);
  // The rear face: the shock arrives at 1 ps; its free surface then moves at 2 u_p until
  // the flyer's release arrives (after 1.6 ps).
  const auto& rear = trace(r.gauges, "rear_surface");
  EXPECT_NEAR(mean(rear, "vx", 0.0, 0.8), 0.0, 1e-3);  // before the elastic precursor (0.93 ps)
  EXPECT_NEAR(mean(rear, "vx", 1.2, 1.5), 2 * up, 0.03 * 2 * up);
  EXPECT_EQ(rear.rows.front()[rear.column("points")], 4.0);  // the outermost column: 4 points across y
}

// The gauge rows do not depend on the thread count (a shorter run).
TEST(C2, GaugesTheSameOnOneAndTwoThreads) {
  const auto c = test::deck_with(test::example("C2_plate_impact_gauges.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.3);
    t["output"].as_table()->insert_or_assign("times", toml::array{0.3});
  });
  const auto [one, two] = test::same_on_one_and_two_threads<2>(c, false);
  ASSERT_EQ(one.gauges.size(), two.gauges.size());
  for (std::size_t k = 0; k < one.gauges.size(); ++k) EXPECT_EQ(one.gauges[k].rows, two.gauges[k].rows);
  EXPECT_EQ(one.gauges[0].rows.size(), 401u);  // every step and the start
}
