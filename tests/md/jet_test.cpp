// The direct-MD jet sample (jet.hpp): its atoms, piston and notch; the piston held at
// rest while the block hits it; the same bits on any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/core/units.hpp"
#include "mpmx/md/jet.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

using namespace mpmx;
using namespace mpmx::md;

namespace {

JetConfig tiny(double temperature = 10.0) {
  JetConfig c;
  c.scale = 0.04;  // 16 x 8 cells, 2-cell piston, 14.4 A notch
  c.cells = {400, 200, 3};
  c.piston_cells = 40;
  c.notch_depth_nm = 36.0;
  c.temperature = temperature;
  c.seed = 5;
  return c;
}

}  // namespace

TEST(Jet, SampleHasPistonAtRestNotchAndBlockAtMinusUp) {
  const JetConfig c = tiny();
  JetGeometry g;
  const System s = build_jet(c, test::copper(), {}, &g);
  const Atoms& a = s.atoms();
  const double lattice = c.lattice_constant;
  ASSERT_EQ(c.nx(), 16);
  ASSERT_EQ(c.ny(), 8);
  ASSERT_EQ(c.npiston(), 2);
  EXPECT_EQ(g.piston_atoms, 4 * 2 * 8 * 3);
  EXPECT_NEAR(g.length, 16 * lattice, 1e-12);
  EXPECT_NEAR(g.notch_tip, g.x0 + g.length - 14.4, 1e-12);
  // Every atom of the full block either kept or inside the V; none kept inside it.
  std::size_t removed = 0;
  const Crystal full = fcc(16, 8, 3, lattice);
  for (std::size_t i = 0; i < full.atoms.size(); ++i) {
    const double tip = 1.0 - std::abs(2.0 * (full.atoms.y[i] + 0.25 * lattice) / g.ly - 1.0);
    removed += full.atoms.x[i] > g.length - 0.25 * lattice - 14.4 * tip;
  }
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(a.size() + removed, full.atoms.size());
  double p[3] = {0, 0, 0};
  std::size_t nblock = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.id[i] <= g.piston_atoms) {
      EXPECT_LT(a.x[i], g.piston_face);
      EXPECT_EQ(a.vx[i], 0.0);
      EXPECT_EQ(a.vy[i], 0.0);
      EXPECT_EQ(a.vz[i], 0.0);
    } else {
      EXPECT_GT(a.x[i], g.piston_face);
      const double tip = 1.0 - std::abs(2.0 * a.y[i] / g.ly - 1.0);
      EXPECT_LT(a.x[i] - g.x0 - 0.25 * lattice, g.length - 0.25 * lattice - 14.4 * tip + 1e-9);
      p[0] += a.vx[i], p[1] += a.vy[i], p[2] += a.vz[i];
      ++nblock;
    }
  }
  EXPECT_NEAR(p[0] / nblock, -25.0, 1e-12);  // -2.5 km/s in Angstrom/ps
  EXPECT_NEAR(p[1] / nblock, 0.0, 1e-12);
  EXPECT_NEAR(p[2] / nblock, 0.0, 1e-12);
  // Free in x: the vacuum is wider than twice the reach plus half the sample.
  EXPECT_GT(s.box().lx - g.length, 2.0 * (s.potential().cutoff() + 1.0) + 0.5 * g.length);
}

TEST(Jet, PistonHeldAtRestWhileTheBlockHitsIt) {
  JetGeometry g;
  System s = build_jet(tiny(), test::copper(), {}, &g);
  std::vector<double> x0(g.piston_atoms + 1), y0(g.piston_atoms + 1);
  for (std::size_t i = 0; i < s.atoms().size(); ++i)
    if (s.atoms().id[i] <= g.piston_atoms) x0[s.atoms().id[i]] = s.atoms().x[i], y0[s.atoms().id[i]] = s.atoms().y[i];
  s.advance(200, 0.001);
  double fmax = 0;
  for (std::size_t i = 0; i < s.atoms().size(); ++i) {
    const auto id = s.atoms().id[i];
    if (id > g.piston_atoms) continue;
    EXPECT_EQ(s.atoms().x[i], x0[id]);
    EXPECT_EQ(s.atoms().y[i], y0[id]);
    EXPECT_EQ(s.atoms().vx[i], 0.0);
    fmax = std::max(fmax, std::abs(s.atoms().fx[i]));
  }
  EXPECT_GT(fmax, 0.1);  // the block pushes on it (eV/A)
}

// `mpmx md --threads N` runs the jet tiled (SystemOptions::threaded): the block hitting
// the piston (atoms near surfaces and the notch: uneven tiles) gives the same positions,
// velocities and per-atom virials, to the bit, on 1, 2 and 3 threads.
TEST(Jet, SameBitsOnAnyThreadCount) {
  auto state = [](int threads) {
    SystemOptions o;
    o.threaded = true;
    o.threads = threads;
    o.tile_atoms = 200;  // several tiles in the small sample
    o.per_atom = true;
    System s = build_jet(tiny(), test::copper(), o, nullptr);
    s.advance(150, 0.001);
    std::vector<double> v;
    const Atoms& a = s.atoms();
    for (const auto* c : {&a.x, &a.y, &a.z, &a.vx, &a.vy, &a.vz, &s.per_atom_virial()}) v.insert(v.end(), c->begin(), c->end());
    v.push_back(s.potential_energy());
    return v;
  };
  const std::vector<double> one = state(1);
  ASSERT_GT(one.size(), 1000u);
  for (const int n : {2, 3}) {
    EXPECT_EQ(test::differing_bits(one, state(n)), 0u) << n << " threads";
  }
}
