// ctest-label: slow
// J2 at CI size (VALIDATION.md J2): the direct MD of examples/J1_direct_md_tiny.toml, then
// the 2-D DDMP-MD of examples/J2_ddmp_md_20x10_1ppc_tiny.toml against its binned maps
// (eq. 7.12 per recorded time and pooled); and the map reader on a hand-made jet run.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "mpmx/core/error.hpp"
#include "mpmx/io/vtk.hpp"
#include "mpmx/reference/jet_history.hpp"
#include "cli_util.hpp"
#include "multiscale/ms_test_util.hpp"

namespace fs = std::filesystem;
using namespace mpmx;

namespace {

// A jet run of 2 records on 3 x 2 bins of 10 x 5 Angstrom starting at x0 = 2, piston face 4.
fs::path fake_jet_run() {
  const fs::path d = test::scratch_dir("fake_jet");
  fs::create_directories(d / "bins");
  std::ofstream(d / "run.json") << "{ \"jet\" : { \"length_A\" : 30.0, \"ly_A\" : 10.0, \"piston_face_A\" : 4.0, "
                                   "\"x0_A\" : 2.0 } }\n";
  io::vtk::Series series((d / "md_bins.pvd").string());
  for (int k = 0; k < 2; ++k) {
    const std::string name = k == 0 ? "md_bins_000000" : "md_bins_000100";
    std::ofstream csv(d / "bins" / (name + ".csv"));
    csv << "ix,iy,x_A,y_A,atoms,density_g_cm3,temperature_K,vx_km_s,vy_km_s,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,"
           "sxz_GPa,syz_GPa\n";
    for (int iy = 0; iy < 2; ++iy)
      for (int ix = 0; ix < 3; ++ix)
        csv << ix << ',' << iy << ',' << 7 + 10 * ix << ',' << 2.5 + 5 * iy << ',' << (ix == 2 && iy == 1 ? 0 : 5)
            << ",8.9,10,0,0," << -(100 * k + 10 * ix + iy) << ",0,0,0,0,0\n";
    series.add(0.1 * k, "vtk/" + name + ".vti");
  }
  return d;
}

}  // namespace

TEST(JetHistory, EachPointReadsTheBinThatHoldsIt) {
  const auto h = reference::JetHistory::read(fake_jet_run().string());
  EXPECT_EQ(h.piston_face_A(), 4.0);
  EXPECT_TRUE(h.has(0.1));
  EXPECT_FALSE(h.has(0.3));
  // Issue 31: a time between records is not a record (it was compared with the nearer one).
  EXPECT_FALSE(h.has(0.05));
  EXPECT_FALSE(h.has(0.07));
  EXPECT_TRUE(h.has(0.1 + 1e-12));  // the rounding of the written times
  {  // A bin with atoms and a nan stress is refused, naming the file and line.
    const fs::path d = fake_jet_run();
    std::string csv = test::slurp(d / "bins" / "md_bins_000100.csv");
    csv.replace(csv.find(",-100,"), 6, ",nan,");
    std::ofstream(d / "bins" / "md_bins_000100.csv") << csv;
    try {
      reference::JetHistory::read(d.string());
      ADD_FAILURE() << "read a bin of nan stress";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("md_bins_000100.csv:2: bin (0, 0) holds 5 atoms"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(h.sxx(0.0, 3.0, 1.0), 0.0);       // bin (0, 0), first record
  EXPECT_EQ(h.sxx(0.1, 13.0, 6.0), -111.0);   // bin (1, 1), second record
  EXPECT_EQ(h.sxx(0.09, 25.0, 1.0), -120.0);  // the nearest record
  EXPECT_EQ(h.sxx(0.1, 13.0, 16.0), -111.0);  // y is periodic
  EXPECT_TRUE(std::isnan(h.sxx(0.1, 25.0, 6.0)));  // an empty bin
  EXPECT_TRUE(std::isnan(h.sxx(0.1, 1.0, 1.0)));   // outside the bins
  EXPECT_THROW(reference::JetHistory::read(test::scratch_dir("not_a_jet")), InputError);
  // A run.json without one of the jet's numbers (or with a key but no number) is named.
  const fs::path d = fake_jet_run();
  for (const std::string& text : {std::string("{ \"jet\" : { \"length_A\" : 30.0, \"ly_A\" : 10.0, "
                                              "\"piston_face_A\" : 4.0 } }\n"),
                                  std::string("{ \"jet\" : { \"length_A\" : 30.0, \"ly_A\" : 10.0, "
                                              "\"piston_face_A\" : 4.0, \"x0_A\" : null } }\n")}) {
    std::ofstream(d / "run.json") << text;
    try {
      reference::JetHistory::read(d.string());
      ADD_FAILURE() << "read a run.json without x0_A";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("jet.x0_A"), std::string::npos) << e.what();
    }
  }
}

TEST(J2Tiny, DdmpMdFollowsTheDirectMdJet) {
  const std::string md = test::scratch_dir("j2_direct_md"), ms = test::scratch_dir("j2_ddmp_md");
  auto run = [](const std::string& cmd) {
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  };
  ASSERT_EQ(run(std::string(MPMX_BINARY) + " md " + MPMX_SOURCE_DIR + "/examples/J1_direct_md_tiny.toml --quiet --out " +
                md + " > " + md + ".log 2>&1"),
            0);
  // The deck names ../runs/J1_direct_md_tiny; here the reference is the run just made.
  const auto c = test::deck_with(test::example("J2_ddmp_md_20x10_1ppc_tiny.toml"), [&](toml::table& t) {
    t["reference"].as_table()->insert_or_assign("file", md);
  });
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 2;
  const auto r = app::run_mpm_dim<2>(c, o);
  // dt = "cfl" at 0.5: more steps than the 60 of the fixed 0.025 ps it had (a Courant
  // number of 0.74 in the shocked crystal), each a whole number of MD steps.
  EXPECT_GT(r.steps, 60);
  EXPECT_EQ(r.state.time, 1.5);
  ASSERT_TRUE(std::isfinite(r.stress_vs_direct_md));
  // Measured 0.326 (1 point per cell, 108-atom boxes; the seed's 50 x 25 cells at 1 point
  // per cell: 0.247): held as a bound until the full-size study runs on a cluster.
  EXPECT_LT(r.stress_vs_direct_md, 0.4);
  EXPECT_GT(r.stress_vs_direct_md, 0.05);
  EXPECT_LT(r.momentum_error(), 1e-9 * r.momentum_scale + 1e-12);
  // The boxes in mixed precision (float pairs, double sums): within 0.5 points of double.
  const auto cm = test::deck_with(test::example("J2_ddmp_md_20x10_1ppc_tiny.toml"), [&](toml::table& t) {
    t["reference"].as_table()->insert_or_assign("file", md);
    t["material"]["md"].as_table()->insert_or_assign("precision", "mixed");
  });
  const auto rm = app::run_mpm_dim<2>(cm, o);
  std::printf("J2 tiny, eq. 7.12: double %.4f, mixed %.4f\n", r.stress_vs_direct_md, rm.stress_vs_direct_md);
  EXPECT_LT(std::abs(rm.stress_vs_direct_md - r.stress_vs_direct_md), 0.005);
}

// The cluster decks pass `mpmx check` for the ranks they are meant for, and one process
// here is refused with the memory figure (never forced).
TEST(J2Decks, ClusterDecksPassCheckForTheirRanks) {
  auto check = [](const std::string& deck, const std::string& extra) {
    const std::string out = test::scratch_dir("j2_check") + "/log";
    const std::string cmd = std::string(MPMX_BINARY) + " check " + MPMX_SOURCE_DIR + "/examples/" + deck + " " + extra +
                            " > " + out + " 2>&1";
    const int st = std::system(cmd.c_str());
    return std::pair{WIFEXITED(st) ? WEXITSTATUS(st) : -1, test::read_file(out)};
  };
  for (const char* deck : {"J2_ddmp_md_100x50_4ppc_full.toml", "J2_ddmp_md_100x50_4ppc_s0p1.toml"}) {
    const auto [code, text] = check(deck, "--ranks 64");
    EXPECT_EQ(code, 0) << text;
    EXPECT_NE(text.find("atom-steps"), std::string::npos) << text;
    EXPECT_NE(text.find("(each of 64 ranks)"), std::string::npos) << text;
    const auto [alone, why] = check(deck, "--ranks 1");
    if (alone != 0) {
      EXPECT_NE(why.find("memory"), std::string::npos) << why;
    }
  }
}
