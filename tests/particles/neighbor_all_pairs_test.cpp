// ctest-label: unit
// The all-pairs list build of small periodic boxes (particles/neighbor_all_pairs.hpp)
// against the binned search it stands in for, on every vector path this machine runs:
// the same list, entry for entry (so the same pairs, each once, and the same order the
// kernels sum in), in random triclinic boxes stretched, compressed and tilted as far as
// Box::reduce_tilt allows, thinner than twice (and than once) the list radius along some
// axis, with one or two atoms per periodic length; and in a 500-atom crystal compressed
// by 30% and sheared, where the size rule takes all pairs, for any thread count. Where no
// edge is shorter than the radius the pairs are also those of brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "mpmx/core/isa.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/neighbor.hpp"

#include "pair_set_util.hpp"

using namespace mpmx;
using particles::Atoms;
using particles::Box;
using particles::Neighbors;

namespace {

Neighbors build_by(Neighbors::Search search, const Atoms& at, const Box& box, double rc, double skin,
                   int threads = 1) {
  Neighbors nb;
  nb.search = search;
  nb.build(at, box, rc, skin, threads);
  return nb;
}

// Moves each atom into the fundamental domain [0, L) (as System::wrap does).
void wrap(Atoms& at, const Box& box) {
  for (std::size_t i = 0; i < at.size(); ++i)
    for (int pass = 0; pass < 3; ++pass) {
      const auto n = box.image_of(at.x[i], at.y[i], at.z[i]);
      const auto s = box.shift(n[0], n[1], n[2]);
      at.x[i] -= s[0], at.y[i] -= s[1], at.z[i] -= s[2];
    }
}

class AllPairs : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { isa_use(GetParam()); }
  void TearDown() override { isa_use(isa_supported().front()); }
};

INSTANTIATE_TEST_SUITE_P(Isa, AllPairs, ::testing::ValuesIn(isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(AllPairs, RandomStrainedTiltedBoxesListTheBinnedSearchsEntries) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int taken = 0, thin = 0, wide = 0, checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double rc = 2.0 + 3.0 * u(rng), skin = 0.2 + 0.8 * u(rng), rs = rc + skin;
    Box box;
    // Edges from 0.35 to 4.5 list radii: most boxes thinner than 2 rs along some axis.
    box.lx = rs * (0.35 + 4.15 * u(rng));
    box.ly = rs * (0.35 + 4.15 * u(rng));
    box.lz = rs * (0.35 + 4.15 * u(rng));
    // Tilts up to half an edge either way (Box::reduce_tilt's bound), or none.
    if (trial % 4 != 0) {
      box.xy = (u(rng) - 0.5) * box.lx;
      box.xz = (u(rng) - 0.5) * box.lx;
      box.yz = (u(rng) - 0.5) * box.ly;
    }
    // Few atoms (one or two per periodic length) to some hundred.
    const int n = trial % 5 == 0 ? 1 + static_cast<int>(3 * u(rng)) : 1 + static_cast<int>(150 * u(rng));
    Atoms at;
    for (int i = 0; i < n; ++i) at.push_back(u(rng) * box.lx, u(rng) * box.ly, u(rng) * box.lz, 0, i);
    // Some atoms on the faces and near the far faces.
    if (n > 2) at.x[0] = 0.0, at.y[1] = std::nextafter(box.ly, 0.0), at.z[2] = 0.0;
    const Neighbors all = build_by(Neighbors::Search::all_pairs, at, box, rc, skin);
    const Neighbors bins = build_by(Neighbors::Search::binned, at, box, rc, skin);
    ASSERT_FALSE(bins.all_pairs_built());
    taken += all.all_pairs_built();
    thin += all.all_pairs_built() && std::min({box.lx, box.ly, box.lz}) < 2 * rs;
    wide += all.all_pairs_built() && std::min({box.lx, box.ly, box.lz}) > 2.01 * rs;
    EXPECT_EQ(all.first, bins.first) << "trial " << trial;
    ASSERT_EQ(all.list, bins.list) << "trial " << trial;
    if (std::min({box.lx, box.ly, box.lz}) >= rs) {
      EXPECT_EQ(test::listed(all), test::pairs_within(at, box, rs)) << "trial " << trial;
      ++checked;
    }
  }
  // Nearly every box takes all pairs when asked (not those too thin for its shift limit),
  // both boxes that try one image per axis and boxes that try several.
  EXPECT_GT(taken, 350);
  EXPECT_GT(thin, 150);
  EXPECT_GT(wide, 50);
  EXPECT_GT(checked, 150);
}

// A 500-atom copper box as a hot point's: compressed by 30% along z, sheared, the atoms
// jittered; the size rule takes all pairs, and the list is the bins' for any threads.
TEST_P(AllPairs, CompressedShearedCrystalBySizeRule) {
  const particles::Crystal c = particles::fcc(5, 5, 5, 3.615);
  std::mt19937 rng(3);
  std::normal_distribution<double> jitter(0.0, 0.15);
  for (const double strain : {0.0, 0.15, 0.30}) {
    Box box = c.box;
    Atoms at = c.atoms;
    const double sz = 1 - strain, shear = 0.4 * strain;
    for (std::size_t i = 0; i < at.size(); ++i) {
      at.x[i] += shear * at.z[i] + jitter(rng);
      at.y[i] += jitter(rng);
      at.z[i] = at.z[i] * sz + jitter(rng);
    }
    box.lz *= sz;
    box.xz = shear * c.box.lz;
    box.reduce_tilt();
    wrap(at, box);
    const double rc = 5.507, skin = 1.0;
    for (const int threads : {1, 3}) {
      const Neighbors rule = build_by(Neighbors::Search::by_size, at, box, rc, skin, threads);
      const Neighbors bins = build_by(Neighbors::Search::binned, at, box, rc, skin);
      EXPECT_TRUE(rule.all_pairs_built()) << "strain " << strain;
      EXPECT_EQ(rule.first, bins.first) << "strain " << strain;
      EXPECT_EQ(rule.list, bins.list) << "strain " << strain;
      EXPECT_EQ(test::listed(rule), test::pairs_within(at, box, rc + skin)) << "strain " << strain;
    }
  }
}

}  // namespace

// The size rule keeps the bins for a large box, an open axis and tiles.
TEST(AllPairsRule, BinsForLargeBoxesOpenAxesAndTiles) {
  const particles::Crystal big = particles::fcc(12, 12, 12, 3.615);
  EXPECT_FALSE(build_by(Neighbors::Search::by_size, big.atoms, big.box, 5.507, 1.0).all_pairs_built());
  const particles::Crystal small = particles::fcc(5, 5, 5, 3.615);
  EXPECT_TRUE(build_by(Neighbors::Search::by_size, small.atoms, small.box, 5.507, 1.0).all_pairs_built());
  Neighbors open;
  open.periodic = {true, false, true};
  open.search = Neighbors::Search::all_pairs;
  open.build(small.atoms, small.box, 5.507, 1.0);
  EXPECT_FALSE(open.all_pairs_built());
  Neighbors tiled;
  tiled.tiles = true;
  tiled.build(small.atoms, small.box, 5.507, 1.0);
  EXPECT_FALSE(tiled.all_pairs_built());
}
