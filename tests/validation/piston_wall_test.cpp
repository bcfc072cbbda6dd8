// ctest-label: validation
// ctest-cost: 10
// C1 (VALIDATION.md): a piston into a bar at rest is the bar sent onto a fixed wall, seen
// from the piston (Galilean). The piston carries the grid (mpm/piston_grid.hpp), so in
// every scheme and dimension it rings no more than the wall: the linear elastic bar of
// C1_piston_elastic_* (rho 8.9, E 233, 2 points per cell along x, linear viscosity 0.5,
// dt 0.01 ps) at u_p = 0.5 km/s, the points 5 to 15 nm from the bar's start at t = 4 ps
// (the piston is at 2 nm, the front near 20.6): the spread of their velocities (max -
// min) on 80 cells within 1.5x the wall's, their median on 400 cells within 1% of the
// wall's and of u_p, and the energy error over the energy in play no larger than the
// wall's. About 6 s for the 18 cases. And from the first step the piston's energy
// balance (kinetic + stored, less its work) is the wall run's, as are run.json's figures.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

constexpr double kUp = 0.5, kEnd = 4.0;

struct Plateau {
  double spread = 0.0, median = 0.0, energy = 0.0;  // energy: the relative error
  std::vector<double> v;  // the points' velocities, in the piston's frame; NaN outside
};

// The deck: the C1 bar in `dim` dimensions (2-D, 3-D: one row of square cells, roller
// faces), `cells` along x, the scheme; a piston at u_p, or (wall) a fixed left face
// and the bar at -u_p; to time `end`.
app::MpmConfig bar(const std::string& scheme, int dim, int cells, bool wall, double end = kEnd) {
  const char* file = dim == 1 ? "C1_piston_elastic_1d.toml" : "C1_piston_elastic_2d.toml";
  return test::deck_with(test::example(file), [&](toml::table& t) {
    const double dx = 40.0 / cells;
    auto& g = *t["grid"].as_table();
    auto& b = *t["boundary"].as_table();
    if (dim == 1) {
      g.insert_or_assign("cells", cells);
    } else {
      toml::array lower, upper, n, per;
      for (int d = 0; d < dim; ++d) {
        lower.push_back(0.0);
        upper.push_back(d == 0 ? 40.0 : dx);
        n.push_back(d == 0 ? cells : 1);
        per.push_back(d == 0 ? 2 : 1);
      }
      g.insert_or_assign("dim", dim);
      g.insert_or_assign("lower", lower);
      g.insert_or_assign("upper", upper);
      g.insert_or_assign("cells", n);
      t["particles"].as_table()->insert_or_assign("per_cell", per);
      if (dim == 3) {
        b.insert_or_assign("z_lower", toml::table{{"type", "roller"}});
        b.insert_or_assign("z_upper", toml::table{{"type", "roller"}});
      }
    }
    auto& s = *t["scheme"].as_table();
    s.insert_or_assign("name", scheme);
    if (scheme == "ddmp_subpoints") s.insert_or_assign("subpoints", dim == 1 ? 4 : 2);
    if (scheme.rfind("ddmp", 0) != 0) s.erase("alpha");
    if (wall) {  // the normal velocity held at zero (a roller: the piston is frictionless)
      b.insert_or_assign(dim == 1 ? "left" : "x_lower", toml::table{{"type", dim == 1 ? "fixed" : "roller"}});
      t.insert_or_assign("initial", toml::table{{"velocity", toml::table{{"value", -kUp}}}});  // along x
    }
    t["time"].as_table()->insert_or_assign("end", end);
    t["output"].as_table()->insert_or_assign("times", toml::array{end});
  });
}

// The points 5 to 15 nm from where the bar started (the wall's moved into the piston's
// frame, x + u_p t and v + u_p).
template <int Dim>
Plateau plateau(const app::RunResultOf<Dim>& r, bool wall) {
  const auto& p = r.state.particles;
  const double shift = wall ? kUp : 0.0;
  Plateau pl;
  std::vector<double> v;
  for (std::size_t q = 0; q < p.size(); ++q) {
    const double x = p.x[0][q] + shift * kEnd;
    const bool in = x > 5.0 && x < 15.0;
    pl.v.push_back(in ? p.v[0][q] + shift : std::nan(""));
    if (in) v.push_back(pl.v.back());
  }
  if (v.empty()) return pl;
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  pl.spread = *hi - *lo;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  pl.median = v[v.size() / 2];
  pl.energy = r.energy_scale() > 0.0 ? r.energy_error() / r.energy_scale() : 0.0;
  return pl;
}

// The largest difference of a point's velocity between the runs, over the points in
// the plateau in both.
double largest_difference(const Plateau& a, const Plateau& b) {
  double d = 0.0;
  for (std::size_t q = 0; q < std::min(a.v.size(), b.v.size()); ++q)
    if (std::isfinite(a.v[q]) && std::isfinite(b.v[q])) d = std::max(d, std::abs(a.v[q] - b.v[q]));
  return d;
}

Plateau measure(const std::string& scheme, int dim, int cells, bool wall) {
  const auto c = bar(scheme, dim, cells, wall);
  if (dim == 1) return plateau<1>(test::run(c), wall);
  if (dim == 2) return plateau<2>(test::run_dim<2>(c), wall);
  return plateau<3>(test::run_dim<3>(c), wall);
}

}  // namespace

class PistonAsWall : public testing::TestWithParam<std::tuple<std::string, int>> {};

TEST_P(PistonAsWall, RingsNoMoreThanTheWall) {
  const auto& [scheme, dim] = GetParam();
  const Plateau p80 = measure(scheme, dim, 80, false), w80 = measure(scheme, dim, 80, true);
  const Plateau p400 = measure(scheme, dim, 400, false), w400 = measure(scheme, dim, 400, true);
  EXPECT_GT(w80.spread, 0.0);
  // The same points, the same velocities: the runs differ only where the bar's far end
  // meets the empty nodes (at rest in the lab, or on the wall's grid), which DDMP's
  // smoothed gradient reads; by t = 4 ps it reaches the plateau at 1e-6 km/s on 80
  // cells (rounding elsewhere: 1e-11).
  EXPECT_LT(largest_difference(p80, w80), 1e-5 * kUp);
  EXPECT_LT(largest_difference(p400, w400), 1e-5 * kUp);
  EXPECT_LE(p80.spread, 1.5 * w80.spread) << "80 cells: piston " << p80.spread << ", wall " << w80.spread;
  EXPECT_NEAR(p400.median, w400.median, 0.01 * kUp);
  EXPECT_NEAR(p400.median, kUp, 0.01 * kUp);
  for (const auto& [p, w] : {std::pair{p80, w80}, std::pair{p400, w400}})
    EXPECT_LE(p.energy, 1.1 * w.energy + 1e-3) << "energy error: piston " << p.energy << ", wall " << w.energy;
  std::printf("%-15s %d-D  spread 80: piston %.4f wall %.4f  median 400: piston %.4f wall %.4f  energy 80: %.4f %.4f"
              "  400: %.4f %.4f  largest difference %.2g %.2g\n",
              scheme.c_str(), dim, p80.spread, w80.spread, p400.median, w400.median, p80.energy, w80.energy,
              p400.energy, w400.energy, largest_difference(p80, w80), largest_difference(p400, w400));
}

INSTANTIATE_TEST_SUITE_P(SchemesAndDimensions, PistonAsWall,
                         testing::Combine(testing::Values("mpm", "ugimp", "cpgimp", "cpdi", "ddmp", "ddmp_subpoints"),
                                          testing::Values(1, 2, 3)),
                         [](const auto& info) {
                           return std::get<0>(info.param) + "_" + std::to_string(std::get<1>(info.param)) + "d";
                         });

namespace {

// A run's figures after its last step: the balance (kinetic + stored, less the
// boundary's work, against the start), the growth the run checks (over its scale),
// run.json's relative error.
struct Balance {
  double imbalance = 0.0, growth = 0.0, relative_error = 0.0, kinetic_initial = 0.0;
};

template <int Dim>
Balance balance(const app::RunResultOf<Dim>& r) {
  return {r.kinetic_final + r.stored_final - r.kinetic_initial - r.stored_initial - r.boundary_work, r.energy_growth,
          r.energy_error() / r.energy_scale(), r.kinetic_initial};
}

Balance measure_balance(const std::string& scheme, int dim, bool wall, double end) {
  const auto c = bar(scheme, dim, 80, wall, end);
  if (dim == 1) return balance<1>(test::run(c));
  if (dim == 2) return balance<2>(test::run_dim<2>(c));
  return balance<3>(test::run_dim<3>(c));
}

}  // namespace

// Steps 1 to 5 (dt 0.01 ps), where the piston's work and the bar's kinetic energy in the
// lab are still near zero and the stored energy runs ahead of the work (the step's
// forces are the stress's at its start): the piston's balance is the wall's to
// round-off, so its total energy changes by its work within the wall's error, and its
// growth and relative error read the wall's (the energy in play is the wall run's: the
// kinetic energy in the grid's frame). Over the lab's scale alone the growth read NaN at
// step 1 and -0.41 at step 2 here (the wall's -0.00037), and +1.015 at step 2 of an
// undamped bar, which stopped the run at time.energy_growth_stop.
TEST(PistonEnergy, IsTheWallsFromTheFirstStep) {
  for (const auto& [scheme, dim] :
       {std::pair{"mpm", 1}, std::pair{"ddmp", 1}, std::pair{"mpm", 2}, std::pair{"cpdi", 3}})
    for (int k = 1; k <= 5; ++k) {
      SCOPED_TRACE(testing::Message() << scheme << " " << dim << "-D, step " << k);
      const Balance p = measure_balance(scheme, dim, false, 0.01 * k), w = measure_balance(scheme, dim, true, 0.01 * k);
      const double round_off = 1e-12 * w.kinetic_initial;
      EXPECT_GT(std::abs(w.imbalance), 1e3 * round_off);  // the wall's error, which the piston's is
      EXPECT_LE(std::abs(p.imbalance), std::abs(w.imbalance) + round_off);
      EXPECT_NEAR(p.imbalance, w.imbalance, round_off);
      EXPECT_NEAR(p.growth, w.growth, 1e-12);
      EXPECT_NEAR(p.relative_error, w.relative_error, 1e-12);
      EXPECT_LT(std::abs(p.growth), 1e-2);
    }
}
