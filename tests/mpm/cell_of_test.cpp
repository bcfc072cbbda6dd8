// ctest-label: unit
// The fused kernels' cell of a point (cell_of): the grid's cells inside, the end cells'
// flat continuation past the ends (eq. 3.9), and a valid cell for any input, NaN and
// infinities included, since the kernels index with it before the off-grid test reports.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mpmx/mpm/fused1d/linear_fused_detail.hpp"

namespace {

using mpmx::mpm::shape::fused::cell_of;

TEST(CellOf, CellAndFractionInsideTheGrid) {
  const double top = 200.0;
  for (const double xi : {0.0, 0.125, 1.0, 57.875, 199.5}) {
    const auto cf = cell_of(xi, top);
    EXPECT_EQ(cf.c, std::floor(xi)) << xi;
    EXPECT_EQ(cf.f, xi - std::floor(xi)) << xi;
  }
  // The upper end belongs to the last cell, at its far side.
  EXPECT_EQ(cell_of(top, top).c, top - 1.0);
  EXPECT_EQ(cell_of(top, top).f, 1.0);
}

TEST(CellOf, PastTheEndsTheEndCellsAtTheirEnds) {
  const double top = 200.0;
  EXPECT_EQ(cell_of(-0.3, top).c, 0.0);
  EXPECT_EQ(cell_of(-0.3, top).f, 0.0);
  EXPECT_EQ(cell_of(200.4, top).c, 199.0);
  EXPECT_EQ(cell_of(200.4, top).f, 1.0);
}

TEST(CellOf, NanAndInfinitiesGiveAValidCell) {
  const double top = 200.0, inf = std::numeric_limits<double>::infinity();
  for (const double xi : {std::nan(""), -inf, inf, -1e300, 1e300}) {
    const auto cf = cell_of(xi, top);
    EXPECT_GE(cf.c, 0.0) << xi;
    EXPECT_LE(cf.c, top - 1.0) << xi;
    EXPECT_GE(cf.f, 0.0) << xi;
    EXPECT_LE(cf.f, 1.0) << xi;
  }
  EXPECT_EQ(cell_of(std::nan(""), top).c, 0.0);
}

}  // namespace
