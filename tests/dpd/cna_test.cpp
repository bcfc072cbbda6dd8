// Common neighbour analysis (fig. 4): a perfect fcc lattice, periodic, is all fcc; an
// hcp lattice is all hcp; a strongly shuffled one has no fcc.
#include <gtest/gtest.h>

#include <cmath>

#include "dpd_test_util.hpp"
#include "mpmx/dpd/cna.hpp"
#include "mpmx/particles/rng.hpp"

using namespace mpmx;

TEST(DpdCna, PerfectFccIsFcc) {
  const double a = test::kCoarseLattice;
  dpd::Particles p = dpd::fcc_block({4, 4, 4}, a, {0, 0, 0}, 1.0, 0, 1);
  const auto c = dpd::common_neighbour_analysis(p, test::cube(4 * a), a);
  EXPECT_DOUBLE_EQ(dpd::fcc_fraction(c), 1.0);
}

TEST(DpdCna, HcpIsHcpAndNoiseIsOther) {
  // hcp: a = 5, c = a sqrt(8/3) in an orthogonal cell of 4 sites (a, a sqrt 3, c).
  const double a = 5.0, c = a * std::sqrt(8.0 / 3.0), b = a * std::sqrt(3.0);
  const int nx = 6, ny = 4, nz = 4;
  dpd::Particles p;
  std::int64_t id = 1;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 1.0 / 6, 0.5}, {0, 2.0 / 3, 0.5}};
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        for (const auto& s : basis) p.push_back((i + s[0]) * a, (j + s[1]) * b, (k + s[2]) * c, 1.0, 0, id++);
  dpd::Domain d = test::cube(1);
  d.box.lx = nx * a, d.box.ly = ny * b, d.box.lz = nz * c;
  const auto codes = dpd::common_neighbour_analysis(p, d, a * std::sqrt(2.0));  // nearest neighbours at a
  for (auto code : codes) ASSERT_EQ(code, dpd::kHcp);
  particles::RngStream rng(7, 0);
  for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += 0.25 * a * rng.normal(), p.y[i] += 0.25 * a * rng.normal();
  EXPECT_LT(dpd::fcc_fraction(dpd::common_neighbour_analysis(p, d, a * std::sqrt(2.0))), 0.01);
}
