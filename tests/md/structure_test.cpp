// Adaptive common neighbour analysis (md/structure.hpp) on crystals built here: perfect
// fcc, hcp and bcc, an icosahedron, the same crystals hot, compressed and sheared (10%), a
// vacancy's neighbours and a free surface; the same labels on any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "mpmx/md/structure.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/rng.hpp"

using namespace mpmx::md;
using mpmx::particles::Crystal;

namespace {

void add(Crystal& c, double x, double y, double z) {
  c.atoms.push_back(x, y, z, 0, static_cast<std::int64_t>(c.atoms.size()) + 1);
}

// Cubic cells of a basis (in units of a).
Crystal cubic(int n, double a, std::initializer_list<std::array<double, 3>> basis) {
  Crystal c;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        for (const auto& b : basis) add(c, (i + b[0]) * a, (j + b[1]) * a, (k + b[2]) * a);
  c.box.lx = c.box.ly = c.box.lz = n * a;
  return c;
}

Crystal bcc(int n, double a) { return cubic(n, a, {{0, 0, 0}, {0.5, 0.5, 0.5}}); }

// Ideal hcp (c/a = sqrt(8/3)) in its orthogonal cell: a x sqrt(3) a x c, four atoms.
Crystal hcp(int nx, int ny, int nz, double a) {
  const double b = std::sqrt(3.0) * a, c = std::sqrt(8.0 / 3.0) * a;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 5.0 / 6, 0.5}, {0, 1.0 / 3, 0.5}};
  Crystal out;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        for (const auto& s : basis) add(out, (i + s[0]) * a, (j + s[1]) * b, (k + s[2]) * c);
  out.box.lx = nx * a, out.box.ly = ny * b, out.box.lz = nz * c;
  return out;
}

std::map<Structure, int> count(const std::vector<Structure>& s) {
  std::map<Structure, int> m;
  for (Structure x : s) ++m[x];
  return m;
}

void jiggle(Crystal& c, double amplitude, std::uint64_t seed) {
  mpmx::particles::RngStream r(seed, 1);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    c.atoms.x[i] += amplitude * (2 * r.uniform() - 1);
    c.atoms.y[i] += amplitude * (2 * r.uniform() - 1);
    c.atoms.z[i] += amplitude * (2 * r.uniform() - 1);
  }
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {  // back into [0, L)
    c.atoms.x[i] -= c.box.lx * std::floor(c.atoms.x[i] / c.box.lx);
    c.atoms.y[i] -= c.box.ly * std::floor(c.atoms.y[i] / c.box.ly);
    c.atoms.z[i] -= c.box.lz * std::floor(c.atoms.z[i] / c.box.lz);
  }
}

}  // namespace

TEST(Structure, PerfectCrystals) {
  const Crystal f = mpmx::particles::fcc(4, 4, 4, 3.615);
  EXPECT_EQ(count(adaptive_cna(f.atoms, f.box, 5.5))[Structure::fcc], 256);
  const Crystal b = bcc(5, 2.855);
  EXPECT_EQ(count(adaptive_cna(b.atoms, b.box, 5.3))[Structure::bcc], 250);
  const Crystal h = hcp(5, 3, 3, 3.2);
  EXPECT_EQ(count(adaptive_cna(h.atoms, h.box, 6.0))[Structure::hcp], 180);
  EXPECT_EQ(structure_name(Structure::hcp), "hcp");
}

TEST(Structure, HotCompressedAndShearedCrystalsKeepTheirLabels) {
  // Atoms jiggled by up to 0.15 A (about 500 K in copper).
  Crystal f = mpmx::particles::fcc(4, 4, 4, 3.615);
  jiggle(f, 0.15, 3);
  EXPECT_EQ(count(adaptive_cna(f.atoms, f.box, 5.5))[Structure::fcc], 256);
  Crystal b = bcc(5, 2.855);
  jiggle(b, 0.1, 4);
  EXPECT_EQ(count(adaptive_cna(b.atoms, b.box, 5.3))[Structure::bcc], 250);
  // 20% uniaxial compression: a fixed cut-off between the shells would fail it, the
  // adaptive one does not.
  Crystal c = mpmx::particles::fcc(4, 4, 4, 3.615, -0.1);
  EXPECT_EQ(count(adaptive_cna(c.atoms, c.box, 5.5))[Structure::fcc], 256);
  // Tilted box: x += 0.1 y (the images slide with it).
  Crystal s = mpmx::particles::fcc(4, 4, 4, 3.615);
  for (std::size_t i = 0; i < s.atoms.size(); ++i) s.atoms.x[i] += 0.1 * s.atoms.y[i];
  s.box.xy = 0.1 * s.box.ly;
  for (std::size_t i = 0; i < s.atoms.size(); ++i) s.atoms.x[i] -= s.box.lx * std::floor(s.atoms.x[i] / s.box.lx);
  EXPECT_EQ(count(adaptive_cna(s.atoms, s.box, 5.5))[Structure::fcc], 256);
}

TEST(Structure, DefectsAreOther) {
  // A vacancy: its 12 neighbours lose fcc, the other 243 keep it.
  Crystal f = mpmx::particles::fcc(4, 4, 4, 3.615);
  mpmx::particles::Atoms a;
  for (std::size_t i = 1; i < f.atoms.size(); ++i) a.push_back(f.atoms.x[i], f.atoms.y[i], f.atoms.z[i], 0, f.atoms.id[i]);
  const auto v = count(adaptive_cna(a, f.box, 5.5));
  EXPECT_EQ(v.at(Structure::other), 12);
  EXPECT_EQ(v.at(Structure::fcc), 243);
  // A slab with free faces along x (vacuum beyond): the outer plane on each side lacks 4
  // of its 12 neighbours; the next plane has all 12 and the bonds among them, so is fcc.
  Crystal slab = mpmx::particles::fcc(6, 4, 4, 3.615);
  slab.box.lx *= 2;
  const auto s = count(adaptive_cna(slab.atoms, slab.box, 5.5));
  EXPECT_EQ(s.at(Structure::fcc) + s.at(Structure::other), 384);
  EXPECT_EQ(s.at(Structure::other), 2 * 32);  // the planes at x = 0 and x = 5.5 a
}

TEST(Structure, Icosahedron) {
  // A 13-atom icosahedral cluster in a big box: the centre is ico, the shell other.
  Crystal c;
  c.box.lx = c.box.ly = c.box.lz = 30;
  const double t = (1 + std::sqrt(5.0)) / 2, s = 2.5 / std::sqrt(1 + t * t);
  add(c, 15, 15, 15);
  for (int p = 0; p < 3; ++p)
    for (int u : {-1, 1})
      for (int w : {-1, 1}) {
        double q[3] = {0, 0, 0};
        q[p] = u * s, q[(p + 1) % 3] = w * t * s;
        add(c, 15 + q[0], 15 + q[1], 15 + q[2]);
      }
  const auto l = adaptive_cna(c.atoms, c.box, 6.0);
  EXPECT_EQ(l[0], Structure::ico);
  EXPECT_EQ(count(l)[Structure::other], 12);
}

TEST(Structure, SameLabelsOnAnyThreadCount) {
  Crystal f = mpmx::particles::fcc(6, 6, 6, 3.615);
  jiggle(f, 0.35, 9);  // hot enough that some atoms are other
  const auto one = adaptive_cna(f.atoms, f.box, 5.5, 1);
  const auto two = adaptive_cna(f.atoms, f.box, 5.5, 2);
  EXPECT_EQ(one, two);
  const auto n = count(one);
  EXPECT_GT(n.at(Structure::fcc), 0);
}
