// ctest-label: unit
// The oriented lattices (particles/oriented_lattice.hpp): the periodic tile's lengths and
// atom count for fcc, bcc, b2 and hcp along [100], [110], [111] and the hcp cell's axes; every
// atom of a box at its crystal's neighbour distance from its nearest (none closer, none
// doubled, across the periodic faces too); fcc along the axes the very bits of fcc();
// refusals of a zero, non-orthogonal, left-handed or (hcp) off-axis set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

using namespace mpmx::particles;

namespace {

LatticeSpec spec(LatticeStyle s, Orient o, double a = 1.0) {
  LatticeSpec l;
  l.style = s;
  l.orient = o;
  l.constant = a;
  return l;
}

const Orient k110 = {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};
const Orient k111 = {{{1, 1, 1}, {-1, 1, 0}, {-1, -1, 2}}};
const Orient kC = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};

// The shortest and the second-shortest distinct distances from atom i to any other atom
// or image (a brute-force check of the crystal the tiles make).
double nearest(const Crystal& c, std::size_t i) {
  double best = INFINITY;
  for (std::size_t j = 0; j < c.atoms.size(); ++j)
    for (int ix = -1; ix <= 1; ++ix)
      for (int iy = -1; iy <= 1; ++iy)
        for (int iz = -1; iz <= 1; ++iz) {
          if (j == i && ix == 0 && iy == 0 && iz == 0) continue;
          const double dx = c.atoms.x[j] + ix * c.box.lx - c.atoms.x[i];
          const double dy = c.atoms.y[j] + iy * c.box.ly - c.atoms.y[i];
          const double dz = c.atoms.z[j] + iz * c.box.lz - c.atoms.z[i];
          best = std::min(best, std::sqrt(dx * dx + dy * dy + dz * dz));
        }
  return best;
}

void expect_tile(const LatticeSpec& s, double lx, double ly, double lz, long atoms) {
  const LatticeTile t = lattice_tile(s);
  EXPECT_NEAR(t.length[0], lx, 1e-12);
  EXPECT_NEAR(t.length[1], ly, 1e-12);
  EXPECT_NEAR(t.length[2], lz, 1e-12);
  EXPECT_EQ(t.atoms, atoms);
}

}  // namespace

TEST(OrientedLattice, TileLengthsAndAtomCounts) {
  const double r2 = std::sqrt(2.0), r3 = std::sqrt(3.0), r6 = std::sqrt(6.0);
  expect_tile(spec(LatticeStyle::fcc, kCubeAxes), 1, 1, 1, 4);
  expect_tile(spec(LatticeStyle::fcc, k110), r2 / 2, r2 / 2, 1, 2);
  expect_tile(spec(LatticeStyle::fcc, k111), r3, r2 / 2, r6 / 2, 6);
  expect_tile(spec(LatticeStyle::bcc, kCubeAxes), 1, 1, 1, 2);
  expect_tile(spec(LatticeStyle::bcc, k110), r2, r2, 1, 4);
  expect_tile(spec(LatticeStyle::bcc, k111), r3 / 2, r2, r6, 6);
  LatticeSpec h = spec(LatticeStyle::hcp, kCubeAxes);
  expect_tile(h, 1, r3, std::sqrt(8.0 / 3.0), 4);
  h.orient = kC;
  h.c_over_a = 1.593;  // Zr's
  expect_tile(h, 1.593, 1, r3, 4);
  // b2 is simple cubic with two sites: [111] repeats after sqrt(3) a, not bcc's half; half
  // its sites are of the second type.
  expect_tile(spec(LatticeStyle::b2, k111), r3, r2, r6, 12);
  const LatticeTile b2 = lattice_tile(spec(LatticeStyle::b2, k110));
  EXPECT_EQ(std::count(b2.kinds.begin(), b2.kinds.end(), 1), 2);
  const Crystal nial = oriented_crystal(spec(LatticeStyle::b2, k111, 2.86), {1, 2, 1}, 0.0, 3);
  EXPECT_EQ(std::count(nial.atoms.type.begin(), nial.atoms.type.end(), 4), 12);
  EXPECT_EQ(std::count(nial.atoms.type.begin(), nial.atoms.type.end(), 3), 12);
  // A tile's atoms fill it at the crystal's density: 4/a^3 (fcc), 2/a^3 (bcc).
  const LatticeTile t = lattice_tile(spec(LatticeStyle::bcc, {{{1, 1, 2}, {1, -1, 0}, {1, 1, -1}}}));
  EXPECT_NEAR(static_cast<double>(t.atoms) / (t.length[0] * t.length[1] * t.length[2]), 2.0, 1e-12);
}

TEST(OrientedLattice, EveryAtomAtItsNeighbourDistance) {
  const double a = 3.3;
  struct Case {
    LatticeSpec s;
    std::array<int, 3> tiles;
  };
  for (const Case& k : {Case{spec(LatticeStyle::fcc, k111, a), {1, 3, 2}}, Case{spec(LatticeStyle::bcc, k110, a), {2, 2, 3}},
                        Case{spec(LatticeStyle::bcc, k111, a), {4, 2, 1}}, Case{spec(LatticeStyle::hcp, kC, a), {2, 3, 2}}}) {
    const Crystal c = oriented_crystal(k.s, k.tiles);
    ASSERT_EQ(static_cast<long>(c.atoms.size()), lattice_tile(k.s).atoms * k.tiles[0] * k.tiles[1] * k.tiles[2]);
    const double nn = a * nearest_neighbour_ratio(k.s);
    for (std::size_t i = 0; i < c.atoms.size(); ++i) {
      EXPECT_NEAR(nearest(c, i), nn, 1e-12) << lattice_name(k.s.style) << " atom " << i;
      EXPECT_GE(c.atoms.x[i], 0.0);
      EXPECT_LT(c.atoms.x[i], c.box.lx);
      EXPECT_EQ(c.atoms.id[i], static_cast<std::int64_t>(i) + 1);
    }
  }
}

TEST(OrientedLattice, FccAlongTheAxesIsFccItself) {
  const Crystal a = oriented_crystal(spec(LatticeStyle::fcc, kCubeAxes, 3.615), {3, 4, 5}, 0.02);
  const Crystal b = fcc(3, 4, 5, 3.615, 0.02);
  ASSERT_EQ(a.atoms.size(), b.atoms.size());
  EXPECT_EQ(std::memcmp(a.atoms.x.data(), b.atoms.x.data(), a.atoms.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.atoms.z.data(), b.atoms.z.data(), a.atoms.size() * sizeof(double)), 0);
  EXPECT_EQ(a.box.lx, b.box.lx);
}

TEST(OrientedLattice, RefusalsSayWhy) {
  auto why = [](LatticeStyle s, Orient o) { return orient_problem(spec(s, o)); };
  EXPECT_EQ(why(LatticeStyle::bcc, k111), "");
  EXPECT_EQ(why(LatticeStyle::hcp, kC), "");
  EXPECT_NE(why(LatticeStyle::bcc, {{{1, 1, 0}, {0, 0, 0}, {0, 0, 1}}}).find("the y direction is the zero vector"),
            std::string::npos);
  EXPECT_NE(why(LatticeStyle::fcc, {{{1, 1, 0}, {-1, 1, 1}, {0, 0, 1}}})
                .find("the y and z directions [-1,1,1] and [0,0,1] are not orthogonal (dot product 1)"),
            std::string::npos);
  EXPECT_NE(why(LatticeStyle::bcc, {{{1, 1, 0}, {1, -1, 0}, {0, 0, 1}}}).find("left-handed"), std::string::npos);
  EXPECT_NE(why(LatticeStyle::hcp, k110).find("the x direction [1,1,0] is off the hcp cell's axes"), std::string::npos);
  EXPECT_THROW(lattice_tile(spec(LatticeStyle::hcp, k110)), mpmx::InputError);
  EXPECT_THROW(oriented_crystal(spec(LatticeStyle::bcc, k110), {0, 1, 1}), mpmx::InputError);
}
