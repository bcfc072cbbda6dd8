// ctest-label: unit
// The neighbour lists both engines use (particles/neighbor.hpp).
//  - The build on every vector path this machine runs: the same list as the scalar
//    path, entry for entry, holding exactly the pairs (any image) within cutoff + skin,
//    each once, each atom's entries ascending; in boxes of random atoms tilted a little
//    and far, with an open axis, and in a crystal large enough that its entries take
//    three radix passes to sort.
//  - The rebuild test measures the atoms' motion against the box's own affine change:
//    while it says the list holds, every pair (images included) within the cutoff must
//    be in the list, for a box sheared and stretched with its atoms and jittered about
//    that flow; and such a box keeps its list for many more steps than the same motion
//    measured from the build positions would allow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mpmx/core/isa.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/neighbor.hpp"

#include "pair_set_util.hpp"

using namespace mpmx;
using particles::Atoms;
using particles::Box;
using particles::Mat3;
using particles::Neighbors;
using test::listed;
using test::pairs_within;

namespace {

// A triclinic box of randomly placed atoms in [0, L) along each axis (where System
// wraps them, Box::image_of): tilted a little, or nearly as far as Box::reduce_tilt
// allows.
std::pair<Atoms, Box> random_box(std::uint32_t seed, bool far) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Box box;
  box.lx = 9.0, box.ly = 8.0, box.lz = 7.5;
  if (far)
    box.xy = 4.0, box.xz = -3.5, box.yz = 3.5;
  else
    box.xy = 0.5, box.xz = -0.5, box.yz = 0.4;
  Atoms at;
  for (int i = 0; i < 120; ++i) at.push_back(u(rng) * box.lx, u(rng) * box.ly, u(rng) * box.lz, 0, i);
  return {at, box};
}

class SearchPath : public ::testing::TestWithParam<std::string> {
 protected:
  void TearDown() override { mpmx::isa_use(mpmx::isa_supported().front()); }
};

Neighbors build_on(const std::string& path, const Atoms& at, const Box& box, double rc, double skin,
                   std::array<bool, 3> periodic) {
  mpmx::isa_use(path);
  Neighbors nb;
  nb.periodic = periodic;
  nb.build(at, box, rc, skin);
  return nb;
}

INSTANTIATE_TEST_SUITE_P(Isa, SearchPath, ::testing::ValuesIn(mpmx::isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(SearchPath, EveryPairWithinTheListRadiusOnceAndTheScalarPathsList) {
  const double rc = 3.0, skin = 0.6;
  for (const std::array<bool, 3> periodic : {std::array{true, true, true}, std::array{true, false, true}}) {
    for (const std::uint32_t seed : {4u, 5u, 6u, 7u}) {
      const auto [at, box] = random_box(seed, seed % 2 == 1);
      const Neighbors nb = build_on(GetParam(), at, box, rc, skin, periodic);
      const Neighbors ref = build_on(mpmx::isa_compiled().back(), at, box, rc, skin, periodic);
      EXPECT_EQ(nb.first, ref.first);
      EXPECT_EQ(nb.list, ref.list);
      EXPECT_EQ(listed(nb), pairs_within(at, box, rc + skin, periodic)) << "seed " << seed;
    }
  }
}

// 70,304 atoms (over 65,536 entries, so that three radix passes sort an atom's
// entries): a perfect fcc crystal with the list radius between the second and third
// shells holds 18 neighbours per atom, 9 pairs per atom in the half list.
TEST_P(SearchPath, LargeCrystalHoldsItsShellsAscending) {
  const particles::Crystal c = particles::fcc(26, 26, 26, 3.615);
  const Neighbors nb = build_on(GetParam(), c.atoms, c.box, 3.5, 0.5, {true, true, true});
  ASSERT_GT(nb.nall, 1 << 16);
  EXPECT_EQ(nb.list.size(), 9 * c.atoms.size());
  for (int i = 0; i < nb.nlocal; ++i)
    for (int s = nb.first[i] + 1; s < nb.first[i + 1]; ++s) ASSERT_LT(nb.list[s - 1], nb.list[s]) << "atom " << i;
  const Neighbors ref = build_on(mpmx::isa_compiled().back(), c.atoms, c.box, 3.5, 0.5, {true, true, true});
  EXPECT_EQ(nb.list, ref.list);
}

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

}  // namespace
