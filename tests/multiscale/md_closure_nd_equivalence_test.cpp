// N1 for the MD closure: the 1-D DDMP-MD bar written as a 2-D and a 3-D deck (one cell
// across y and z, roller faces, sub-points along x only, the axis-product alpha that
// reduces to the 1-D one, no mass distribution, no eq. 7.11, the deck's linear
// viscosity) gives every point the 1-D run's x-velocity, stress and position at 0 K.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ms_test_util.hpp"

using namespace mpmx;

namespace {

// The tiny bar as a Dim-D deck: the same points along x, one cell across.
app::MpmConfig bar_nd(int dim, int points, int cells, int steps) {
  const auto one = test::tiny_bar(points, cells, steps);
  return test::deck_with(test::example("H2_strong_0K_256_small.toml"), [&](toml::table& t) {
    const double length = one.upper - one.lower, dx = length / points;
    toml::array lower{0.0}, upper{length}, grid_cells{points}, per{1}, sub{8}, normal{1.0};
    for (int d = 1; d < dim; ++d)
      lower.push_back(0.0), upper.push_back(dx), grid_cells.push_back(1), per.push_back(1), sub.push_back(1),
          normal.push_back(0.0);
    auto& g = *t["grid"].as_table();
    g.insert_or_assign("dim", dim);
    g.insert_or_assign("lower", lower);
    g.insert_or_assign("upper", upper);
    g.insert_or_assign("cells", grid_cells);
    t["particles"].as_table()->insert_or_assign("per_cell", per);
    auto& s = *t["scheme"].as_table();
    s.insert_or_assign("subpoints", sub);
    s.insert_or_assign("alpha", "axis_product");
    auto* md = t["material"]["md"].as_table();
    md->insert_or_assign("cells", cells);
    md->insert_or_assign("energy_consistency", false);
    auto& strain = *t["initial"]["strain"].as_table();
    strain.insert_or_assign("cells", 2.0);
    strain.insert_or_assign("normal", normal);
    auto& b = *t["boundary"].as_table();
    b.erase("left"), b.erase("right");
    toml::table fixed, roller;
    fixed.insert("type", "fixed"), roller.insert("type", "roller");
    b.insert_or_assign("x_lower", fixed), b.insert_or_assign("x_upper", fixed);
    for (const char* face : {"y_lower", "y_upper", "z_lower", "z_upper"})
      if (face[0] == 'y' || dim == 3) b.insert_or_assign(face, roller);
    toml::table md_off;
    md_off.insert("on", false);
    t.insert_or_assign("mass_distribution", md_off);
    t["time"].as_table()->insert_or_assign("end", 0.1 * steps);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
    t.erase("reference");
  });
}

template <int Dim>
void expect_same_as_1d(const app::RunResult& one, const app::RunResultOf<Dim>& nd, double tol, const char* what) {
  const auto& p1 = one.state.particles;
  const auto& pn = nd.state.particles;
  ASSERT_EQ(p1.size(), pn.size()) << what;
  double dv = 0, ds = 0, dx = 0, sv = 0, ss = 0, sx = 0;
  for (std::size_t q = 0; q < p1.size(); ++q) {
    dv = std::max(dv, std::abs(p1.v[0][q] - pn.v[0][q])), sv = std::max(sv, std::abs(p1.v[0][q]));
    ds = std::max(ds, std::abs(p1.stress[0][q] - pn.stress[0][q])), ss = std::max(ss, std::abs(p1.stress[0][q]));
    dx = std::max(dx, std::abs(p1.x[0][q] - pn.x[0][q])), sx = std::max(sx, std::abs(p1.x[0][q]));
  }
  EXPECT_LE(dv, tol * sv) << what << ": x-velocity";
  EXPECT_LE(ds, tol * ss) << what << ": stress";
  EXPECT_LE(dx, tol * sx) << what << ": position";
  EXPECT_GT(ss, 1.0) << what;  // GPa: the bar is compressed
}

}  // namespace

TEST(N1, MdClosureBarIn2DAnd3DEqualsTheOneDimensionalRun) {
  const int points = 12, cells = 2, steps = 6;
  const auto one = test::run(test::tiny_bar(points, cells, steps));
  const auto two = test::run_dim<2>(bar_nd(2, points, cells, steps));
  expect_same_as_1d<2>(one, two, 1e-10, "2-D");
  const auto three = test::run_dim<3>(bar_nd(3, points, cells, steps));
  expect_same_as_1d<3>(one, three, 1e-10, "3-D");
}
