// ctest-label: unit
// The neighbour list's rebuild test measures the atoms' motion against the box's own
// affine change: while it says the list holds, every pair (images included) within the
// cutoff must be in the list, for a box sheared and stretched with its atoms and jittered
// about that flow; and such a box keeps its list for many more steps than the same motion
// measured from the build positions would allow.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpmx/md/neighbor.hpp"

#include "pair_set_util.hpp"

using namespace mpmx::md;
using mpmx::test::listed;
using mpmx::test::pairs_within;

TEST(NeighborRebuild, ListHoldsEveryClosePairUnderAffineFlow) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double rc = 3.0, skin = 0.6;
  Box box;
  box.lx = 9.0, box.ly = 8.0, box.lz = 7.5, box.xy = 1.0, box.xz = -0.5, box.yz = 0.7;
  Atoms at;
  for (int i = 0; i < 90; ++i) {
    const double f[3] = {u(rng), u(rng), u(rng)};
    at.push_back(f[0] * box.lx + f[1] * box.xy + f[2] * box.xz, f[1] * box.ly + f[2] * box.yz, f[2] * box.lz,
                 0, i);
  }
  // Atoms into the fundamental box, then the list (as System::rebuild does).
  auto wrap_and_build = [&](Neighbors& nb) {
    for (std::size_t i = 0; i < at.size(); ++i) {
      const auto n = box.image_of(at.x[i], at.y[i], at.z[i]);
      const auto s = box.shift(n[0], n[1], n[2]);
      at.x[i] -= s[0], at.y[i] -= s[1], at.z[i] -= s[2];
    }
    nb.build(at, box, rc, skin);
  };
  Neighbors nb;
  wrap_and_build(nb);
  // A shear and a stretch (upper triangular, per step), the atoms carried along and
  // jittered a little.
  const Mat3 g{0.004, 0.006, -0.003, 0.0, -0.005, 0.004, 0.0, 0.0, 0.003};
  std::normal_distribution<double> jitter(0.0, 0.002);
  int holds = 0, rebuilds = 0, moved_half_skin = 0;
  for (int step = 0; step < 120; ++step) {
    for (std::size_t i = 0; i < at.size(); ++i) {
      const double x = at.x[i], y = at.y[i], z = at.z[i];
      at.x[i] += g[0] * x + g[1] * y + g[2] * z + jitter(rng);
      at.y[i] += g[4] * y + g[5] * z + jitter(rng);
      at.z[i] += g[8] * z + jitter(rng);
    }
    box.deform(g, 1.0);
    if (nb.needs_rebuild(at, box)) {
      ++rebuilds;
      wrap_and_build(nb);
      continue;
    }
    ++holds;
    double d2 = 0.0;  // the old measure: motion from the build positions
    for (std::size_t i = 0; i < at.size(); ++i) {
      const double dx = at.x[i] - nb.x_at_build()[i], dy = at.y[i] - nb.y_at_build()[i], dz = at.z[i] - nb.z_at_build()[i];
      d2 = std::max(d2, dx * dx + dy * dy + dz * dz);
    }
    moved_half_skin += std::sqrt(d2) > 0.5 * skin;
    const auto close = pairs_within(at, box, rc);
    const auto have = listed(nb);
    for (const auto& p : close) ASSERT_TRUE(have.count(p)) << "step " << step << ": a pair within the cutoff is missing";
  }
  EXPECT_GT(holds, 80);
  EXPECT_GE(rebuilds, 3);  // the strain alone spends the skin now and then
  // Steps the list held although some atom had moved more than half the skin from where
  // it was at the build: the old test would have rebuilt on each of them.
  EXPECT_GT(moved_half_skin, holds / 2);
}

// A box gone non-finite asks for no rebuild (building from it would cast NaN image
// counts to integers): the run's finiteness check stops it and names the step.
TEST(NeighborRebuild, NonFiniteBoxAsksForNoRebuild) {
  Box box;
  box.lx = box.ly = box.lz = 8.0;
  Atoms at;
  at.push_back(1.0, 2.0, 3.0, 0, 0);
  at.push_back(2.5, 2.0, 3.0, 0, 1);
  Neighbors nb;
  nb.build(at, box, 3.0, 0.5);
  box.lx = std::nan("");
  EXPECT_FALSE(nb.needs_rebuild(at, box));
  box.lx = 8.0;
  at.x[0] = 3.0;  // moved by 2 > skin / 2
  EXPECT_TRUE(nb.needs_rebuild(at, box));
}
