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

namespace md_elastic_warnings {

// At 300 K (issue 53, item 2: "at a temperature by averaging"): the strained boxes held
// at 300 K by velocity rescaling, their stresses averaged. Mishin Cu at its 300 K
// constant (3.632 A, docs/md.md's NPT) softens from 0 K's 169.9, 122.6, 76.2 GPa by a
// few percent; the tensor keeps its cubic symmetry within its errors.
TEST(MdElastic, CopperAt300K) {
  const std::string deck = R"([potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.632
cells = [3, 3, 3]
[run]
dt = 0.002
steps = 0
[elastic]
temperature = 300
equilibrate_steps = 1000
sample_steps = 3000
)";
  const auto path = mpmx::test::scratch_file("cu_elastic_300.toml", deck);
  const auto out = mpmx::test::scratch_root() / "cu_elastic_300";
  const auto r = run_cli("md " + path.string() + " --out " + out.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("and 300 K: C11"), std::string::npos) << r.output;
  const std::string json = slurp(out / "run.json");
  const auto cubic = json.substr(json.find("\"cubic\""));
  const double c11 = mpmx::test::json_number(cubic, "c11"), c12 = mpmx::test::json_number(cubic, "c12"),
               c44 = mpmx::test::json_number(cubic, "c44");
  EXPECT_GT(c11, 150.0);
  EXPECT_LT(c11, 169.0);
  EXPECT_GT(c12, 110.0);
  EXPECT_LT(c12, 125.0);
  EXPECT_GT(c44, 68.0);
  EXPECT_LT(c44, 76.5);
  EXPECT_NE(json.find("\"box_frame_error_GPa\""), std::string::npos);

  // The 0 K minimum is no hot crystal's constant: refused with the reason.
  const auto bad = mpmx::test::scratch_file("cu_elastic_bad.toml", deck + "at = \"minimum\"\n");
  const auto b = run_cli("md " + bad.string() + " --check");
  EXPECT_EQ(b.status, 2) << b.output;
  EXPECT_NE(b.output.find("elastic.at"), std::string::npos) << b.output;
}

}  // namespace md_elastic_warnings
