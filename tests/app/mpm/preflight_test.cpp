// What a continuum run checks before its work, and `mpmx check` with it (app/mpm/
// preflight.hpp): bodies whose shapes are wrong (zero area, crossing edges, coordinates
// that overflow), bodies that place no point (off the grid, removed whole, a deck that
// only removes), bodies that claim one point with different motions, a spin over the CFL
// limit, a convergence study sized by its finest grid, a reference not there yet, an
// md_closure count past an int. `check` and `run` agree on every one.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "cli_util.hpp"
#include "md/md_test_util.hpp"
#include "mpm/mpm_test_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/preflight.hpp"
#include "mpmx/core/error.hpp"

namespace {

using namespace mpmx;

// A linear elastic deck on the unit square or cube: `cells` cells and `per` points per
// cell along each axis, no bodies yet.
std::string grid_deck(int dim, int cells, int per) {
  auto axes = [dim](const std::string& v) {
    std::string s = "[" + v;
    for (int d = 1; d < dim; ++d) s += ", " + v;
    return s + "]";
  };
  return "[case]\nid = \"P\"\n[grid]\ndim = " + std::to_string(dim) + "\nlower = " + axes("0.0") +
         "\nupper = " + axes("1.0") + "\ncells = " + axes(std::to_string(cells)) + "\n[particles]\nper_cell = " +
         axes(std::to_string(per)) +
         "\n[scheme]\nname = \"mpm\"\n[material]\nmodel = \"linear_elastic\"\ndensity = 1.0\n"
         "youngs_modulus = 1.0\n[time]\ndt = 1e-3\nend = 1e-2\n[output]\nplot = false\nvtk = false\n";
}

const std::string k2d = grid_deck(2, 10, 2);
const std::string k3d = grid_deck(3, 4, 1);

// The error of reading the deck and its pre-flight, or "" when both pass.
std::string mpm_refusal(const std::string& text, std::uint64_t memory = 0) {
  try {
    const auto c = app::read_mpm_deck_text(text, "p.toml");
    app::preflight_mpm_run(c, 1, memory, false);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(MpmPreflight, PolygonOfZeroAreaIsRefused) {
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"polygon\"\nvertices = [0.1, 0.1, 0.5, 0.5, 0.9, 0.9]\n"),
             "[[body]] 0: polygon has zero area");
}

TEST(MpmPreflight, SelfCrossingPolygonNamesItsEdges) {
  const std::string e = mpm_refusal(k2d + "[[body]]\nshape = \"polygon\"\n"
                                          "vertices = [0.1, 0.1, 0.9, 0.9, 0.9, 0.1, 0.1, 0.9]\n");
  EXPECT_HAS(e, "[[body]] 0: polygon edges 1 (0.1, 0.1)-(0.9, 0.9) and 3 (0.9, 0.1)-(0.1, 0.9) cross");
  // A simple one with a notch (concave) is fine.
  EXPECT_EQ(mpm_refusal(k2d + "[[body]]\nshape = \"polygon\"\n"
                              "vertices = [0.1, 0.1, 0.9, 0.1, 0.9, 0.9, 0.5, 0.4, 0.1, 0.9]\n"),
            "");
}

TEST(MpmPreflight, OverflowingCoordinatesAreRefused) {
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"polygon\"\nvertices = [0.0, 0.0, 1e308, 0.0, 0.0, 1e308]\n"),
             "[[body]] 0: 1e+308 is beyond 1e+100 in magnitude");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"circle\"\ncenter = [0.5, 0.5]\nradius = 1e200\n"),
             "[[body]] 0: 1e+200 is beyond");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"box\"\nlower = [-1e300, 0.0]\nupper = [1e300, 1.0]\n"), "beyond");
  std::string wide = k2d;
  wide.replace(wide.find("lower = [0.0, 0.0]"), 18, "lower = [-1.7e308, 0.0]");
  wide.replace(wide.find("upper = [1.0, 1.0]"), 18, "upper = [1.7e308, 1.0]");
  EXPECT_HAS(mpm_refusal(wide), "upper - lower overflows");
}

TEST(MpmPreflight, BodiesThatPlaceNoPointAreNamed) {
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"box\"\nlower = [5.0, 5.0]\nupper = [6.0, 6.0]\n"),
             "[[body]] 0: holds no point: it lies wholly off the grid");
  EXPECT_HAS(mpm_refusal(k3d + "[[body]]\nshape = \"sphere\"\ncenter = [5.0, 5.0, 5.0]\nradius = 0.5\n"),
             "[[body]] 0: holds no point: it lies wholly off the grid");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"circle\"\ncenter = [0.5, 0.5]\nradius = 0.01\n"),
             "[[body]] 0: holds no point: it lies between the grid's points");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"box\"\nlower = [0.0, 0.0]\nupper = [1.0, 1.0]\n"
                               "[[body]]\nshape = \"box\"\nremove = true\nlower = [-1.0, -1.0]\nupper = [2.0, 2.0]\n"),
             "[[body]] 0: places no point: each of the 400 points it holds is removed");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"box\"\nremove = true\nlower = [0.2, 0.2]\nupper = [0.4, 0.4]\n"),
             "[[body]] 0: removes points, but no body adds any");
  EXPECT_HAS(mpm_refusal(k2d + "[[body]]\nshape = \"box\"\nlower = [0.0, 0.0]\nupper = [0.5, 1.0]\n"
                               "[[body]]\nshape = \"box\"\nremove = true\nlower = [0.7, 0.2]\nupper = [0.9, 0.4]\n"),
             "[[body]] 1: removes no point: it overlaps no adding body");
}

TEST(MpmPreflight, OverlappingBodiesOfDifferentMotionAreRefused) {
  const std::string two = k2d + "[[body]]\nshape = \"box\"\nlower = [0.1, 0.1]\nupper = [0.6, 0.6]\nvelocity = [V, 0.0]\n"
                                "[[body]]\nshape = \"box\"\nlower = [0.4, 0.4]\nupper = [0.9, 0.9]\n";
  std::string moving = two;
  moving.replace(moving.find('V'), 1, "0.1");
  EXPECT_HAS(mpm_refusal(moving),
             "[[body]] 0 and [[body]] 1 overlap (16 points lie in both) with different velocities or materials");
  std::string same = two;
  same.replace(same.find('V'), 1, "0.0");
  EXPECT_EQ(mpm_refusal(same), "");  // one solid given as two boxes
}

TEST(MpmPreflight, SpinCountsInTheCflLimit) {
  const std::string spin = k2d + "[[body]]\nshape = \"circle\"\ncenter = [0.5, 0.5]\nradius = 0.3\nangular_velocity = ";
  EXPECT_HAS(mpm_refusal(spin + "1e8\n"), "key 'time.dt' = 0.001: exceeds the CFL limit");
  EXPECT_EQ(mpm_refusal(spin + "1.0\n"), "");
}

TEST(MpmPreflight, ConvergenceStudyIsSizedByItsFinestGrid) {
  auto study = [](int levels) {
    std::string t = k2d + "[manufactured]\n[reference]\nname = \"manufactured\"\nfields = [\"displacement\"]\n"
                          "times = [0.01]\n[convergence]\nlevels = " + std::to_string(levels) + "\n";
    return t;
  };
  const auto one = app::preflight_mpm(app::read_mpm_deck_text(study(1), "p.toml"), 1, 0, true).budget;
  const auto four = app::preflight_mpm(app::read_mpm_deck_text(study(4), "p.toml"), 1, 0, true).budget;
  EXPECT_NEAR(four.points, 64.0 * one.points, 1e-9 * four.points);  // (2^3)^2 the points of level 0
  EXPECT_GT(four.bytes, one.bytes);
  EXPECT_EQ(four.levels, 4);
  // 1 + 2^3 + 4^3 + 8^3 times the point-steps of level 0 (2^D points x 2 steps a level).
  EXPECT_NEAR(four.seconds / one.seconds, 1.0 + 8.0 + 64.0 + 512.0, 1e-6 * 585.0);
  // Eight levels of a 160 x 160 grid: the finest has 20480^2 cells; refused on 24 GiB naming the key.
  std::string big = study(8);
  big.replace(big.find("cells = [10, 10]"), 16, "cells = [160, 160]");  // grid_deck(2, 10, 2)
  const std::string e = mpm_refusal(big, std::uint64_t{24} << 30);
  EXPECT_HAS(e, "convergence.levels = 8 (its finest grid");
  EXPECT_HAS(e, "more than this machine's 24 GiB");
}

TEST(MpmPreflight, CheckNamesAReferenceNotThereYetAndRunRefusesIt) {
  auto c = test::deck_with(test::example("H2_strong_0K_256_small.toml"), [](toml::table& t) {
    t["reference"].as_table()->insert_or_assign("file", "no_such_direct_md_run/bar_stress.csv");
  });
  const auto pre = app::preflight_mpm(c, 1, 0, true);
  EXPECT_HAS(pre.pending, "is not there yet");
  try {
    app::preflight_mpm_run(c, 1, 0, true);
    ADD_FAILURE() << "run accepted a reference that is not there";
  } catch (const InputError& e) {
    EXPECT_HAS(std::string(e.what()), "is not there yet");
  }
}

// A 2-D direct-MD reference folder with no records (a header-only md_bins.pvd), or with
// none at all: refused by both.
TEST(MpmPreflight, HeaderOnly2dReferenceIsRefused) {
  namespace fs = std::filesystem;
  const fs::path empty = test::scratch_root() / "jet_ref_empty", header = test::scratch_root() / "jet_ref_header";
  fs::create_directories(empty);
  fs::create_directories(header / "bins");
  std::ofstream(header / "md_bins.pvd") << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
                                           "<Collection>\n</Collection>\n</VTKFile>\n";
  std::ofstream(header / "run.json") << "{\"jet\": {\"piston_face_A\": 1.0, \"x0_A\": 0.0, \"length_A\": 10.0, "
                                        "\"ly_A\": 10.0}}\n";
  for (const auto& [folder, why] : {std::pair<fs::path, std::string>{empty, "has no md_bins.pvd"}, {header, "lists no records"}}) {
    const fs::path dir = folder;  // a lambda captures a copy (clang 14 takes no structured binding)
    auto c = test::deck_with(test::example("J2_ddmp_md_20x10_1ppc_tiny.toml"), [&](toml::table& t) {
      t["reference"].as_table()->insert_or_assign("file", dir.string());
    });
    try {
      app::preflight_mpm(c, 1, 0, true);
      ADD_FAILURE() << "check accepted " << dir;
    } catch (const InputError& e) {
      EXPECT_HAS(std::string(e.what()), why);
    }
  }
}

TEST(MpmPreflight, MdClosureRelaxStepsPastAnIntAreRefused) {
  try {
    test::deck_with(test::example("H2_strong_0K_256_small.toml"), [](toml::table& t) {
      t["material"]["md"].as_table()->insert_or_assign("relax_steps", std::int64_t{4294967298});
    });
    ADD_FAILURE() << "relax_steps = 2^32 + 2 was read (a box advances an int of steps: it wrapped to 2)";
  } catch (const InputError& e) {
    EXPECT_HAS(std::string(e.what()), "key 'material.md.relax_steps' = 4294967298: out of range");
  }
}

// `mpmx check` and `mpmx run` give the same verdict: the run refuses before it writes.
TEST(MpmPreflight, CheckAndRunAgree) {
  const auto bad = test::scratch_file("preflight_off_grid.toml",
                                      k2d + "[[body]]\nshape = \"box\"\nlower = [5.0, 5.0]\nupper = [6.0, 6.0]\n");
  const auto check = test::run_cli("check " + bad.string());
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_HAS(check.output, "[[body]] 0: holds no point");
  const auto out = test::scratch_root() / "preflight_off_grid_out";
  const auto run = test::run_cli("run " + bad.string() + " --quiet --no-plot --out " + out.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_HAS(run.output, "[[body]] 0: holds no point");
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

// `check` bounded for every deck (issue 45): a count too large is refused from the counts,
// before a point is placed or a step counted. Before, per_cell = 10^6 in 2-D placed points
// for the rate timing for minutes, and dt = "cfl" to 1e300 printed -9223372036854775808 steps.
TEST(MpmPreflight, AMillionPointsPerCellAxisIsRefusedFromTheCounts) {
  std::string text = grid_deck(2, 20, 1);
  text.replace(text.find("per_cell = [1, 1]"), 17, "per_cell = 1000000");
  const std::string why = mpm_refusal(text, 24ull << 30);
  EXPECT_HAS(why, "particles.per_cell and grid.cells: 4e+14 points");
  EXPECT_HAS(why, "more than this machine's 24 GiB");
}

TEST(MpmPreflight, StepCountsPastWhatARunCountsAreRefused) {
  std::string text = grid_deck(2, 10, 2);
  text.replace(text.find("end = 1e-2"), 10, "end = 1e300");
  EXPECT_HAS(mpm_refusal(text), "key 'time.end' = 1e+300: is 1e+303 steps of dt = 0.001: more than the 1e+15");
  text.replace(text.find("dt = 1e-3"), 9, "dt = \"cfl\"");
  const std::string why = mpm_refusal(text);
  EXPECT_HAS(why, "key 'time.end' = 1e+300: is ");
  EXPECT_HAS(why, "(the CFL condition's at the start): more than the 1e+15 a run may take");
}
