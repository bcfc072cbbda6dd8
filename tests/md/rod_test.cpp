// The all-atom flyer-on-rod sample (md/rod.hpp): the flyer then the target along x, open on
// every side; the flyer a rigid body, held while the target equilibrates, then free: it
// moves as one under the total force on it, so the system's momentum is kept; the same
// bits on any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/sutton_chen.hpp"
#include "mpmx/md/rod.hpp"
#include "mpmx/md/system.hpp"

#include "md_test_util.hpp"

using namespace mpmx;
using namespace mpmx::md;

namespace {

RodConfig small_rod(double temperature = 300.0) {
  RodConfig c;
  c.lattice_constant = 3.615;
  c.target_cells = {8, 3, 3};
  c.flyer_cells = 2;
  c.temperature = temperature;
  c.seed = 7;
  return c;
}

Vec3 momentum(const System& s, std::int64_t from_id, std::int64_t to_id) {
  Vec3 p{0, 0, 0};
  const Atoms& a = s.atoms();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.id[i] < from_id || a.id[i] > to_id) continue;
    const double m = s.type_mass()[a.type[i]];
    p[0] += m * a.vx[i], p[1] += m * a.vy[i], p[2] += m * a.vz[i];
  }
  return p;
}

}  // namespace

TEST(Rod, SampleHasTheFlyerAtRestAndTheTargetAtTwiceTheTemperatureInVacuum) {
  RodGeometry g;
  const System s = build_rod(small_rod(), test::copper(), {}, &g);
  const Atoms& a = s.atoms();
  ASSERT_EQ(a.size(), 4u * 10 * 3 * 3);
  EXPECT_EQ(g.flyer_atoms, 4 * 2 * 3 * 3);
  EXPECT_EQ(s.frozen_ids(), g.flyer_atoms);
  EXPECT_FALSE(s.rigid_free());
  EXPECT_NEAR(g.impact_face, 2 * 3.615, 1e-12);
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x[3] = {a.x[i], a.y[i], a.z[i]};
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
    const double deck_x = a.x[i] - g.offset[0];
    if (a.id[i] <= g.flyer_atoms) {
      EXPECT_LT(deck_x, g.impact_face - 0.5);
      EXPECT_EQ(a.vx[i], 0.0);
      EXPECT_EQ(a.vy[i], 0.0);
    } else {
      EXPECT_GT(deck_x, g.impact_face - 1e-9);
    }
  }
  // No pair reaches across the vacuum to an image: every gap exceeds the reach.
  const double reach = test::copper().cutoff() + SystemOptions{}.skin;
  const double extent[3] = {s.box().lx, s.box().ly, s.box().lz};
  for (int d = 0; d < 3; ++d) EXPECT_GT(extent[d] - (hi[d] - lo[d]), reach) << d;
  const Vec3 p = momentum(s, g.flyer_atoms + 1, 1 << 30);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(p[d], 0.0, 1e-9);
  // The target at twice the temperature (3N-3 of its own degrees of freedom).
  System t = s;
  t.rescale_temperature(300.0, g.flyer_atoms);  // from 600 K: every velocity times 1/sqrt(2)
  const Atoms& b = t.atoms();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.id[i] > g.flyer_atoms) {
      EXPECT_NEAR(b.vx[i], a.vx[i] / std::sqrt(2.0), 1e-12);
    }
}

TEST(Rod, HeldFlyerStaysAtRestAndTheFreeOneMovesAsOneBodyKeepingTheMomentum) {
  RodGeometry g;
  System s = build_rod(small_rod(), test::copper(), {}, &g);
  s.advance(100, 0.002);
  const Atoms& a = s.atoms();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.id[i] <= g.flyer_atoms) {
      ASSERT_EQ(a.vx[i], 0.0);
    }
  const Vec3 before = momentum(s, 0, 1 << 30);  // the flyer at rest: the target's (the held flyer took some)
  s.release_rigid({5.0, 0.0, 0.0});
  EXPECT_TRUE(s.rigid_free());
  const double flyer_mass = static_cast<double>(g.flyer_atoms) * s.type_mass()[0];
  const Vec3 start = momentum(s, 0, 1 << 30);
  EXPECT_NEAR(start[0], before[0] + 5.0 * flyer_mass, 1e-9 * flyer_mass);
  s.advance(300, 0.002);  // through the impact
  double v[3] = {0, 0, 0};
  bool first = true, one_body = true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (s.atoms().id[i] > g.flyer_atoms) continue;
    const double w[3] = {s.atoms().vx[i], s.atoms().vy[i], s.atoms().vz[i]};
    if (first) std::copy(w, w + 3, v), first = false;
    one_body = one_body && w[0] == v[0] && w[1] == v[1] && w[2] == v[2];
  }
  EXPECT_TRUE(one_body);
  EXPECT_LT(v[0], 4.5);  // the target pushed back
  EXPECT_GT(v[0], 0.0);
  const Vec3 end = momentum(s, 0, 1 << 30);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(end[d], start[d], 1e-9 * 5.0 * flyer_mass) << d;
}

// `mpmx md --threads N` runs the rod tiled: the impact gives the same positions and
// velocities, to the bit, on 1 and 2 threads.
TEST(Rod, SameBitsOnAnyThreadCount) {
  auto state = [](int threads) {
    SystemOptions o;
    o.threaded = true;
    o.threads = threads;
    o.tile_atoms = 100;  // several tiles in the small sample
    System s = build_rod(small_rod(), test::copper(), o, nullptr);
    s.advance(50, 0.002);
    s.rescale_temperature(300.0, 72);
    s.release_rigid({5.0, 0.0, 0.0});
    s.advance(150, 0.002);
    std::vector<double> v;
    const Atoms& a = s.atoms();
    for (const auto* c : {&a.x, &a.y, &a.z, &a.vx, &a.vy, &a.vz}) v.insert(v.end(), c->begin(), c->end());
    v.push_back(s.potential_energy());
    return v;
  };
  const std::vector<double> one = state(1);
  ASSERT_GT(one.size(), 1000u);
  EXPECT_EQ(test::differing_bits(one, state(2)), 0u);
}

TEST(Rod, RefusesAnEmptySample) {
  RodConfig c = small_rod();
  c.flyer_cells = 0;
  EXPECT_THROW(build_rod(c, test::copper(), {}, nullptr), InputError);
  c = small_rod();
  c.target_cells[1] = 0;
  EXPECT_THROW(build_rod(c, test::copper(), {}, nullptr), InputError);
}

// Sutton-Chen (the D decks' MD potential) runs the generic EAM loop; threaded, over tiles
// (eam_compute_tiles): the same forces, energy and per-atom virial as the scattering loop
// to round-off, and the same bits on 1, 2 and 3 threads through the impact.
TEST(Rod, SuttonChenTilesAgreeWithTheScatterLoopAndGiveTheSameBitsOnAnyThreadCount) {
  SuttonChenSpec sc;
  sc.epsilon = 1.2382e-2, sc.a = 3.61, sc.c = 39.432, sc.n = 9, sc.m = 6, sc.cutoff = 9.0, sc.mass = 63.546;
  const Potential pot(sc);
  RodConfig c = small_rod();
  c.lattice_constant = 3.6414;
  auto state = [&](bool tiled, int threads) {
    SystemOptions o;
    o.threaded = tiled;
    o.threads = threads;
    o.tile_atoms = 100;
    o.per_atom = true;
    System s = build_rod(c, pot, o, nullptr);
    s.release_rigid({5.0, 0.0, 0.0});
    s.advance(60, 0.002);
    std::vector<double> v;
    const Atoms& a = s.atoms();
    for (const auto* f : {&a.x, &a.vx, &a.fx, &a.fy, &a.fz, &s.per_atom_virial()}) v.insert(v.end(), f->begin(), f->end());
    v.push_back(s.potential_energy());
    for (double w : s.virial()) v.push_back(w);
    return v;
  };
  const std::vector<double> scatter = state(false, 1), one = state(true, 1);
  ASSERT_EQ(scatter.size(), one.size());
  double worst = 0;
  for (std::size_t k = 0; k < one.size(); ++k) worst = std::max(worst, std::abs(one[k] - scatter[k]) / (1.0 + std::abs(scatter[k])));
  EXPECT_LT(worst, 1e-9);
  for (const int n : {2, 3}) EXPECT_EQ(test::differing_bits(one, state(true, n)), 0u) << n << " threads";
}
