// The direct-MD jet sample (jet.hpp) and its 2-D bins (bins2d.hpp): the sample's atoms,
// piston and notch; the binned stress of a uniform compressed block equal to the box
// stress of eq. 2.25; the piston held at rest; the shock front and speed helpers; and
// [jet] deck errors that name the key, the value and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/config.hpp"
#include "mpmx/md/jet.hpp"
#include "mpmx/md/jet_run.hpp"
#include "mpmx/md/lattice.hpp"
#include "mpmx/md/system.hpp"

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
    const std::vector<double> many = state(n);
    ASSERT_EQ(many.size(), one.size());
    std::size_t differ = 0;
    for (std::size_t k = 0; k < one.size(); ++k) differ += std::memcmp(&one[k], &many[k], sizeof(double)) != 0;
    EXPECT_EQ(differ, 0u) << n << " threads";
  }
}

// A periodic, homogeneously strained perfect crystal moving as a whole: every bin holds
// the same atoms (bins a whole number of cells, planes off the bin edges), so each bin's
// stress of eq. 2.25 is the box's, to round-off.
TEST(JetBins, UniformCompressedBlockEqualsBoxStress) {
  const double a = 3.615, ex = -0.08, ey = -0.03;
  Crystal cr = fcc(8, 4, 3, a, ex);
  for (auto& y : cr.atoms.y) y *= 1 + ey;
  cr.box.ly *= 1 + ey;
  for (std::size_t i = 0; i < cr.atoms.size(); ++i) {  // a quarter plane spacing off the edges
    cr.atoms.x[i] += 0.125 * a * (1 + ex);
    cr.atoms.y[i] += 0.125 * a * (1 + ey);
  }
  SystemOptions o;
  o.per_atom = true;
  System s(cr, test::copper(), o);
  Atoms& at = s.edit_atoms();
  for (std::size_t i = 0; i < at.size(); ++i) at.vx[i] = -25.0, at.vy[i] = 3.0, at.vz[i] = 1.0;
  s.refresh();
  const Mat3 box = s.stress();
  ASSERT_LT(box[0], -0.05);  // about -13 GPa... compressed
  BinGrid g;
  g.nx = 4, g.ny = 2;
  g.x0 = 0, g.dx = s.box().lx / 4, g.dy = s.box().ly / 2, g.lz = s.box().lz;
  const BinFields f = bin_fields(s.snapshot(), s.type_mass(), s.per_atom_virial(), g);
  const double scale = std::abs(box[0]);
  for (int b = 0; b < 8; ++b) {
    EXPECT_EQ(f.atoms[b], static_cast<int>(at.size()) / 8);
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(f.stress[b][k], box[k], 1e-12 * scale) << "bin " << b << " k " << k;
    EXPECT_NEAR(f.vx[b], -25.0, 1e-12);
    EXPECT_NEAR(f.temperature[b], 0.0, 1e-9);
    EXPECT_NEAR(f.density_g_cm3(b), 8.93 / ((1 + ex) * (1 + ey)), 0.01);
  }
}

TEST(JetBins, TemperatureAboutTheBinMean) {
  Crystal cr = fcc(4, 4, 4, 3.615);
  SystemOptions o;
  o.per_atom = true;
  System s(cr, test::copper(), o);
  s.thermalize(150.0, 3, 0);  // kinetic temperature exactly 300 K over 3N - 3
  BinGrid g;
  g.nx = 1, g.ny = 1, g.x0 = 0, g.dx = s.box().lx, g.dy = s.box().ly, g.lz = s.box().lz;
  const BinFields f = bin_fields(s.snapshot(), s.type_mass(), s.per_atom_virial(), g);
  EXPECT_NEAR(f.temperature[0], s.temperature(), 1e-9 * s.temperature());
  const Mat3 box = s.stress();
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(f.stress[0][k], box[k], 1e-12 * std::abs(box[0]) + 1e-15);
}

TEST(JetFront, InterpolatesWhereTheColumnVelocityCrossesHalfUp) {
  BinFields col;
  col.grid.nx = 6, col.grid.ny = 1, col.grid.x0 = 0, col.grid.dx = 2;
  col.atoms = {10, 10, 10, 10, 10, 0};
  col.vx = {0, -1, -5, -20, -25, 0};  // centres 1, 3, 5, 7, 9
  // Between x = 5 (v = -5) and 7 (v = -20): -12.5 at 5 + 2 * 7.5 / 15 = 6.
  EXPECT_NEAR(shock_front(col, 0.0, 25.0), 6.0, 1e-12);
  EXPECT_TRUE(std::isnan(shock_front(col, 8.0, 25.0)));  // first block column unshocked
  // Speed: the records inside (piston + width, tip(t) - width) only.
  const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4, 0.5}, x{1.0, 10.0, 15.0, 20.0, 25.0, 90.0};
  EXPECT_NEAR(shock_speed(t, x, 0.0, 100.0, 25.0, 5.0), 50.0, 1e-9);
  EXPECT_TRUE(std::isnan(shock_speed(t, x, 0.0, 20.0, 25.0, 5.0)));
}

TEST(JetDeck, ErrorsNameKeyValueAndReason) {
  const std::string head = R"(
[potential]
file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.615
cells = [1, 1, 1]
[run]
dt = 0.001
)";
  auto error_of = [&](const std::string& run_extra, const std::string& jet) {
    auto deck = io::Deck::from_string(head + run_extra + "[jet]\n" + jet, "jet.toml");
    try {
      (void)read_md_config(deck);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string good = "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\nbins = [8, 4]\n"
                           "duration_ps = 30.0\nrecord_every_ps = 1.0\n";
  EXPECT_EQ(error_of("", good + "scale = 0.04\n"), "");
  auto has = [](const std::string& msg, const std::string& part) {
    return msg.find(part) != std::string::npos;
  };
  EXPECT_TRUE(has(error_of("steps = 100\n", good), "run.steps")) << error_of("steps = 100\n", good);
  const std::string neg = error_of("", good + "scale = -1.0\n");
  EXPECT_TRUE(has(neg, "jet.scale") && has(neg, "-1") && has(neg, "(0, 10]")) << neg;
  const std::string nan = error_of("", good + "scale = nan\n");
  EXPECT_TRUE(has(nan, "jet.scale")) << nan;
  const std::string deep = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 140.0\n"
                                        "bins = [8, 4]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(deep, "jet.notch_depth_nm") && has(deep, "shallower")) << deep;
  const std::string bins = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                        "bins = [8]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(bins, "jet.bins")) << bins;
  const std::string every = error_of("", good + "scale = 0.0001\n");
  EXPECT_TRUE(has(every, "jet.record_every_ps")) << every;
  const std::string big = error_of("", "cells = [400, 200, 1000000]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                       "bins = [8, 4]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(big, "jet.cells") && has(big, "1000000")) << big;
  const std::string many = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                        "bins = [100000, 100000]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(many, "jet.bins") && has(many, "10^7")) << many;
}
