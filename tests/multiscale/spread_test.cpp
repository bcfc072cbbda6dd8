// Which rank owns which material points: equal contiguous blocks, and blocks of equal
// measured cost for the rebalance (multiscale/spread).
#include <gtest/gtest.h>

#include <vector>

#include "mpmx/multiscale/spread.hpp"

namespace {

using mpmx::multiscale::Spread;

std::vector<std::size_t> starts(const Spread& s) {
  std::vector<std::size_t> v;
  for (int r = 0; r <= s.ranks(); ++r) v.push_back(s.start(r));
  return v;
}

TEST(Spread, EqualBlocksDifferByAtMostOne) {
  EXPECT_EQ(starts(Spread(7, 3, 0)), (std::vector<std::size_t>{0, 2, 4, 7}));
  EXPECT_EQ(starts(Spread(6, 3, 1)), (std::vector<std::size_t>{0, 2, 4, 6}));
  EXPECT_EQ(starts(Spread(2, 3, 2)), (std::vector<std::size_t>{0, 0, 1, 2}));
  const Spread s(7, 3, 2);
  EXPECT_EQ(s.begin(), 4u);
  EXPECT_EQ(s.count(), 3u);
  EXPECT_TRUE(s.owns(6));
  EXPECT_FALSE(s.owns(3));
}

TEST(Spread, BalancedBlocksCarryEqualCost) {
  // Compressed points (the first three) cost three times as much.
  const std::vector<double> cost{3, 3, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1};  // total 18
  EXPECT_EQ(starts(Spread::balanced(cost, 2, 0)), (std::vector<std::size_t>{0, 3, 12}));  // 9 | 9
  EXPECT_EQ(starts(Spread::balanced(cost, 3, 0)), (std::vector<std::size_t>{0, 2, 6, 12}));  // 6 | 6 | 6
  // Equal costs give blocks that differ by at most one; no cost measured, the equal blocks.
  EXPECT_EQ(starts(Spread::balanced(std::vector<double>(7, 1.0), 3, 0)), (std::vector<std::size_t>{0, 2, 5, 7}));
  EXPECT_EQ(starts(Spread::balanced(std::vector<double>(7, 0.0), 3, 0)), starts(Spread(7, 3, 0)));
  // Every rank keeps a point, however lopsided the cost.
  EXPECT_EQ(starts(Spread::balanced({100, 1, 1, 1}, 3, 0)), (std::vector<std::size_t>{0, 1, 2, 4}));
  EXPECT_EQ(starts(Spread::balanced({1, 1, 1, 100}, 3, 0)), (std::vector<std::size_t>{0, 2, 3, 4}));
}

}  // namespace
