// Plane strain kept whole: a 2-D run carries sigma_zz (D_zz = 0), each law its own, and
// writes pressure as -tr(sigma)/3 with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ms_test_util.hpp"

using namespace mpmx;

namespace {

double largest_abs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

}  // namespace

// Isotropic elasticity in plane strain: sigma_zz = nu (sigma_xx + sigma_yy) at every point
// of a disk that has hit a wall (shear, rotation and both normal stresses present).
TEST(PlaneStrain, LinearElasticSigmaZzIsNuTimesTheInPlaneTrace) {
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 1.5);  // in contact
  });
  const auto r = test::run_dim<2>(c);
  const auto& p = r.state.particles;
  ASSERT_EQ(p.stress_zz.size(), p.size());
  const double nu = 0.3, scale = largest_abs(p.stress[0]);
  ASSERT_GT(scale, 0.0);
  double worst = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q)
    worst = std::max(worst, std::abs(p.stress_zz[q] - nu * (p.stress[0][q] + p.stress[3][q])));
  EXPECT_LT(worst, 1e-12 * scale);
  EXPECT_GT(largest_abs(p.stress_zz), 0.1 * scale);
}

// Mie-Gruneisen keeps its deviator whole (3 x 3): under the planar shock of N6 the strain
// is uniaxial along x, so sigma_zz equals sigma_yy (not zero), both -p + s_yy, up to the
// small D_yy the grid's smoothing leaves (measured 1.2e-5 of the shock stress).
TEST(PlaneStrain, MieGruneisenSigmaZzEqualsSigmaYyInAPlanarShock) {
  const auto c = test::deck_with(test::example("N6_copper_planar_impact.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.3);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
  });
  const auto r = test::run_dim<2>(c);
  const auto& p = r.state.particles;
  const double scale = largest_abs(p.stress[0]);
  ASSERT_GT(scale, 10.0);  // GPa: shocked
  double worst = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) worst = std::max(worst, std::abs(p.stress_zz[q] - p.stress[3][q]));
  EXPECT_LT(worst, 1e-4 * scale);
  EXPECT_GT(largest_abs(p.stress_zz), 0.5 * scale);
}

// An MD box's own sigma_zz reaches the point. At 0 K a flyer's uniaxial push along x
// strains each box along x only: by the cubic crystal's symmetry sigma_zz = sigma_yy.
TEST(PlaneStrain, MdBoxSigmaZzReachesThePoint) {
  const auto c = app::read_mpm_deck_text(test::flyer_2d_deck(0.0, 4), "md_closure_2d");
  const auto r = test::run_dim<2>(c);
  const auto& p = r.state.particles;
  const double scale = largest_abs(p.stress[0]);
  ASSERT_GT(scale, 0.1);
  double worst = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) worst = std::max(worst, std::abs(p.stress_zz[q] - p.stress[3][q]));
  EXPECT_LT(worst, 1e-6 * scale);
  EXPECT_GT(largest_abs(p.stress_zz), 0.1 * scale);
}
