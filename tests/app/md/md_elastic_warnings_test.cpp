// `mpmx md` decks and the numbers a user sees (issue 53, items 2 and 5): a deck's
// [elastic] writes the 0 K tensor of its crystal to run.json and the terminal (bcc Ta of
// CuTa: LAMMPS's 264.4, 159.5, 80.9 GPa; the full crosscheck is elastic_lammps_crosscheck);
// an element put on a lattice its file names otherwise, where that lattice lies higher
// in energy, and a box built far from zero stress are warned of by `--check` and the run,
// while a deck that builds the potential's own crystal hears nothing (CuTa names Ta fcc;
// its bcc lies lower). [elastic] beside a [bar] is refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../../md/md_test_util.hpp"
#include "cli_util.hpp"

namespace md_elastic_warnings {

namespace fs = std::filesystem;
using mpmx::test::run_cli;
using mpmx::test::slurp;

std::string deck(const std::string& element, const std::string& lattice, double a, const std::string& more = "") {
  return "[potential]\nstyle = \"eam\"\nfile = \"CuTa.eam.alloy\"\nelements = [\"" + element + "\"]\n" +
         "[lattice]\ntype = \"" + lattice + "\"\nconstant = " + std::to_string(a) + "\ncells = [3, 3, 3]\n" +
         "[run]\ndt = 0.001\nsteps = 0\n" + more;
}

TEST(MdElastic, TaTensorInRunJsonAndOnTheTerminal) {
  const auto path = mpmx::test::scratch_file("ta_elastic.toml", deck("Ta", "bcc", 3.3026, "[elastic]\n"));
  const auto out = mpmx::test::scratch_root() / "ta_elastic";
  const auto r = run_cli("md " + path.string() + " --check");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("elastic: the 0 K tensor"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("warning"), std::string::npos) << r.output;  // Ta's own crystal: nothing to say
  const auto run = run_cli("md " + path.string() + " --out " + out.string() + " -q");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("C11 264.39, C12 159.54, C44 80.88 GPa"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("warning"), std::string::npos) << run.output;
  const std::string json = slurp(out / "run.json");
  EXPECT_NEAR(mpmx::test::json_number(json, "c11"), 264.39, 0.01);
  EXPECT_NEAR(mpmx::test::json_number(json, "c44"), 80.88, 0.01);
  EXPECT_NE(json.find("\"born_stable\" : true"), std::string::npos);
  EXPECT_NE(json.find("\"crystal_axes_GPa\""), std::string::npos);
}

TEST(MdElastic, RefusedBesideABar) {
  const auto path = mpmx::test::scratch_file(
      "bar_elastic.toml", deck("Ta", "bcc", 3.3026, "[elastic]\n[bar]\ncells_x = 10\ncells_yz = 3\n"));
  const auto r = run_cli("md " + path.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("[elastic]"), std::string::npos) << r.output;
}

TEST(MdDeckWarnings, CopperOnABccLatticeIsSaid) {
  const auto path = mpmx::test::scratch_file("cu_bcc.toml", deck("Cu", "bcc", 3.3026));
  const auto r = run_cli("md " + path.string() + " --check");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("warning: the deck builds Cu on a bcc lattice, but CuTa.eam.alloy declares Cu fcc"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("warning: the static bcc box at a = 3.3026 A is stressed"), std::string::npos) << r.output;
  // The run says the same before it starts.
  const auto out = mpmx::test::scratch_root() / "cu_bcc";
  const auto run = run_cli("md " + path.string() + " --out " + out.string() + " -q");
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("md: warning: the deck builds Cu on a bcc lattice"), std::string::npos) << run.output;
}

TEST(MdDeckWarnings, AConstantFarFromTheFilesIsSaid) {
  const auto path = mpmx::test::scratch_file("cu_far.toml", deck("Cu", "fcc", 3.9));
  const auto r = run_cli("md " + path.string() + " --check");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("lattice constant 3.9 A is +7.9% from the file's"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rests at a = 3.61"), std::string::npos) << r.output;
}

}  // namespace md_elastic_warnings
