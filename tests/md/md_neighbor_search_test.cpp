// ctest-label: unit
// The neighbour-list build on every vector path this machine runs: the same list as the
// scalar path, entry for entry, holding exactly the pairs (any image) within cutoff +
// skin, each once, each atom's entries ascending; in boxes of random atoms tilted a
// little and far, with an open axis, and in a crystal
// large enough that its entries take three radix passes to sort.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "mpmx/md/lattice.hpp"
#include "mpmx/md/neighbor.hpp"
#include "mpmx/core/isa.hpp"

#include "pair_set_util.hpp"

using namespace mpmx;
using md::Atoms;
using md::Box;
using md::Neighbors;
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

}  // namespace

INSTANTIATE_TEST_SUITE_P(Isa, SearchPath, ::testing::ValuesIn(mpmx::isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(SearchPath, EveryPairWithinTheListRadiusOnceAndTheScalarPathsList) {
  const double rc = 3.0, skin = 0.6;
  for (const std::array<bool, 3> periodic : {std::array{true, true, true}, std::array{true, false, true}}) {
    for (const std::uint32_t seed : {4u, 5u, 6u, 7u}) {
      const auto [at, box] = random_box(seed, seed % 2 == 1);
      const Neighbors nb = build_on(GetParam(), at, box, rc, skin, periodic);
      const Neighbors ref = build_on("scalar", at, box, rc, skin, periodic);
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
  const md::Crystal c = md::fcc(26, 26, 26, 3.615);
  const Neighbors nb = build_on(GetParam(), c.atoms, c.box, 3.5, 0.5, {true, true, true});
  ASSERT_GT(nb.nall, 1 << 16);
  EXPECT_EQ(nb.list.size(), 9 * c.atoms.size());
  for (int i = 0; i < nb.nlocal; ++i)
    for (int s = nb.first[i] + 1; s < nb.first[i + 1]; ++s) ASSERT_LT(nb.list[s - 1], nb.list[s]) << "atom " << i;
  const Neighbors ref = build_on("scalar", c.atoms, c.box, 3.5, 0.5, {true, true, true});
  EXPECT_EQ(nb.list, ref.list);
}
