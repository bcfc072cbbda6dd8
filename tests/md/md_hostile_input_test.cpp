// Hostile MD input (issue 17): potential file headers that would wrap or exhaust memory,
// nan in a file, an empty file, and the memory and work estimates of MD decks.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/budget.hpp"
#include "mpmx/md/config.hpp"
#include "mpmx/md/potential/eam_file.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;

namespace {

const std::string kCu = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";

std::string read_text(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The Mishin Cu file with line `line` (1-based) replaced.
std::string cu_with_line(int line, const std::string& text) {
  std::istringstream in(read_text(kCu));
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) out += (n == line ? text : l) + "\n";
  return out;
}

std::string error_of(const std::string& path) {
  try {
    read_eam(path);
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string write(const std::string& name, const std::string& text) {
  return mpmx::test::scratch_file(name, text).string();
}

}  // namespace

TEST(EamFileHostile, HeaderCountsAboveTheLimitAreRefusedBeforeAllocating) {
  // 2e9 points would be 16 GB a table: refused on the header line with count and limit.
  auto msg = error_of(write("Cu_2e9.eam.alloy", cu_with_line(5, "2000000000 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_2e9.eam.alloy:5: nrho = 2000000000: out of range: expected from 5 to 10000000 grid "
                     "points"),
            std::string::npos)
      << msg;
  // 1e12 does not fit in 32 bits: before, it wrapped to a negative nrho.
  msg = error_of(write("Cu_1e12.eam.alloy", cu_with_line(5, "10001 0.0002 1000000000000 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_1e12.eam.alloy:5: nr = 1000000000000: out of range: expected from 5 to 10000000"),
            std::string::npos)
      << msg;
  msg = error_of(write("Cu_1e12f.eam.alloy", cu_with_line(5, "1e12 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_1e12f.eam.alloy:5: expected an integer (nrho), found '1e12'"), std::string::npos) << msg;
  msg = error_of(write("Cu_big64.eam.alloy", cu_with_line(5, "99999999999999999999999 0.1 10001 0.0009 5.5")));
  EXPECT_NE(msg.find(":5: nrho = 99999999999999999999999: out of range"), std::string::npos) << msg;
  msg = error_of(write("Cu_nel.eam.alloy", cu_with_line(4, "4294967297 Cu")));
  EXPECT_NE(msg.find(":4: number of elements = 4294967297: out of range: expected from 1 to 100 elements"),
            std::string::npos)
      << msg;
}

TEST(EamFileHostile, CountsTheFileCannotHoldAreRefusedOnTheHeader) {
  // Within the limit, but ten times more values than the file has: refused on line 5
  // (not after sizing tables by the claim).
  const auto msg =
      error_of(write("Cu_claim.eam.alloy", cu_with_line(5, "9000000 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_claim.eam.alloy:5: 1 element(s) with nrho = 9000000 and nr = 10001 promise"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("but the rest of the file holds"), std::string::npos) << msg;
}

TEST(EamFileHostile, NanAndInfInTheFileAreRefusedWithTheLine) {
  auto msg = error_of(write("Cu_nan.eam.alloy", cu_with_line(5, "10001 nan 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_nan.eam.alloy:5: expected a finite number (drho), found 'nan'"), std::string::npos)
      << msg;
  msg = error_of(write("Cu_inf.eam.alloy", cu_with_line(8, "inf 1 2 3 4")));
  EXPECT_NE(msg.find("Cu_inf.eam.alloy:8: expected a finite number (F(rho) of Cu), found 'inf'"),
            std::string::npos)
      << msg;
}

TEST(EamFileHostile, EmptyFileAndDirectoryAreNamed) {
  auto msg = error_of(write("Empty.eam.alloy", ""));
  EXPECT_NE(msg.find("Empty.eam.alloy: the EAM potential file is empty"), std::string::npos) << msg;
  const auto dir = mpmx::test::scratch_root() / "Dir.eam.alloy";
  std::filesystem::create_directories(dir);
  msg = error_of(dir.string());
  EXPECT_NE(msg.find("Dir.eam.alloy: is a directory"), std::string::npos) << msg;
}

namespace {

MdConfig config_of(const std::string& text) {
  auto deck = mpmx::io::Deck::from_string(text, "budget.toml");
  return read_md_config(deck);
}

std::string budget_error(const MdBudget& b, std::uint64_t memory, bool force) {
  try {
    check_md_budget(b, memory, force);
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "";
}

const std::string kLj = R"(
[potential]
style = "lj"
epsilon = 0.4
sigma = 2.3
cutoff = 5.0
mass = 63.5
[lattice]
constant = 3.615
cells = [CELLS]
[run]
dt = 0.001
steps = STEPS
)";

std::string lj(const std::string& cells, const std::string& steps) {
  std::string t = kLj;
  t.replace(t.find("CELLS"), 5, cells);
  t.replace(t.find("STEPS"), 5, steps);
  return t;
}

}  // namespace

TEST(MdBudget, AThousandCubedLatticeIsRefusedForMemoryEvenWhenForced) {
  const auto c = config_of(lj("1000, 1000, 1000", "10"));
  const auto b = estimate_md(c, 5.0);
  EXPECT_EQ(b.atoms, 4e9);
  EXPECT_GT(b.bytes, 4e9 * 300);
  const std::uint64_t memory = 64ull << 30;
  const auto msg = budget_error(b, memory, /*force=*/true);
  EXPECT_NE(msg.find("lattice.cells: 4e+09 atoms need about"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than this machine's 64 GiB"), std::string::npos) << msg;
}

TEST(MdBudget, WorkAboveADayIsRefusedUnlessForced) {
  // 500 atoms x 1e9 steps = 5e11 atom-steps.
  const auto c = config_of(lj("5", "1000000000"));
  const auto b = estimate_md(c, 5.0);
  EXPECT_EQ(b.atom_steps, 5e11);
  const auto msg = budget_error(b, 64ull << 30, false);
  EXPECT_NE(msg.find("run.steps: 500 atoms x 1e+09 steps = 5e+11 atom-steps"), std::string::npos) << msg;
  EXPECT_NE(msg.find("without --force"), std::string::npos) << msg;
  EXPECT_EQ(budget_error(b, 64ull << 30, true), "");
  // The largest int64 step count: the product is figured in floating point, no overflow.
  const auto c2 = config_of(lj("5", "9223372036854775807"));
  EXPECT_NE(budget_error(estimate_md(c2, 5.0), 64ull << 30, false).find("run.steps: 500 atoms x 9.223e+18"),
            std::string::npos);
}

TEST(MdBudget, EstimateIsCloseToMeasuredPeakMemory) {
  // Peak RSS measured with `mpmx md --threads 2` on Cu EAM (cutoff 5.507): 32,000 atoms
  // 86.7 MB, 131,072 atoms 303 MB, 340,736 atoms 743 MB (the constants in budget.cpp were
  // fitted to these).
  auto c = config_of(lj("20", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 86.7e6, 1.0, 0.15);
  c = config_of(lj("32", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 303e6, 1.0, 0.15);
  c = config_of(lj("44", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 743e6, 1.0, 0.15);
}

TEST(MdConfigHostile, IntegersAreRangeCheckedNotWrapped) {
  auto error = [](const std::string& text) {
    try {
      config_of(text);
    } catch (const mpmx::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  std::string t = lj("5", "10");
  t += "[scan]\nlattice_from = 3.5\nlattice_to = 3.7\npoints = 4294967299\n";
  auto msg = error(t);
  EXPECT_NE(msg.find("key 'scan.points' = 4294967299: out of range: must be an integer from 3 to 100000"),
            std::string::npos)
      << msg;
  t = lj("4294967297, 5, 5", "10");
  msg = error(t);
  EXPECT_NE(msg.find("key 'lattice.cells' = [4294967297, 5, 5]: entry 1 = 4294967297: out of range: must be "
                     "an integer from 1 to 1000"),
            std::string::npos)
      << msg;
  t = lj("5", "10");
  t.replace(t.find("style = \"lj\""), 12, "style = \"sutton_chen\"\na = 3.61\nc = 39.4\nn = 9\nm = 4294967302");
  t.replace(t.find("sigma = 2.3\n"), 12, "");
  msg = error(t);
  EXPECT_NE(msg.find("key 'potential.m' = 4294967302: out of range: must be an integer from 1 to 100"),
            std::string::npos)
      << msg;
  t = lj("5", "10") + "[bar]\ncells_x = 40\ncells_yz = 4\nbins = 4294967396\n";
  msg = error(t);
  EXPECT_NE(msg.find("key 'bar.bins' = 4294967396: out of range: must be an integer from 1 to 100000"),
            std::string::npos)
      << msg;
  t = lj("5", "1e6");
  msg = error(t);
  EXPECT_NE(msg.find("key 'run.steps' = 1000000.0: expected an integer, got a number"), std::string::npos) << msg;
  t = lj("5", "10") + "thermo = 4294967396\n";
  msg = error(t);
  EXPECT_NE(msg.find("key 'run.thermo' = 4294967396: out of range: must be an integer from 1 to 2147483647"),
            std::string::npos)
      << msg;
}

TEST(MdConfigHostile, NanVelocityGradientIsRefusedAtReadTime) {
  std::string t = lj("5", "10") + "velocity_gradient_per_ps = [0, 0, 0, 0, nan, 0, 0, 0, 0]\n";
  try {
    config_of(t);
    FAIL() << "nan accepted";
  } catch (const mpmx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'run.velocity_gradient_per_ps' = [0, 0, 0, 0, nan, 0, 0, 0, 0]: "
                                         "entry 5 is nan"),
              std::string::npos)
        << e.what();
  }
}

TEST(MdConfigHostile, PotentialFileIsParsedAndItsElementsCheckedAtReadTime) {
  const std::string empty = write("Empty2.eam.alloy", "");
  auto error = [](const std::string& text) {
    try {
      config_of(text);
    } catch (const mpmx::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string eam = "[potential]\nstyle = \"eam\"\nfile = \"FILE\"\nelements = [ELEMENTS]\n"
                          "[lattice]\nconstant = 3.615\ncells = [3]\n[run]\ndt = 0.001\nsteps = 10\n";
  auto deck = [&](const std::string& file, const std::string& elements) {
    std::string t = eam;
    t.replace(t.find("FILE"), 4, file);
    t.replace(t.find("ELEMENTS"), 8, elements);
    return t;
  };
  auto msg = error(deck(empty, "\"Cu\""));
  EXPECT_NE(msg.find("key 'potential.file'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the EAM potential file is empty"), std::string::npos) << msg;
  msg = error(deck(kCu, "\"Cu\", \"Zr\""));
  EXPECT_NE(msg.find("key 'potential.elements' = [\"Cu\", \"Zr\"]: element 'Zr' is not in"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("(it has: Cu)"), std::string::npos) << msg;
  EXPECT_EQ(error(deck(kCu, "\"Cu\"")), "(no error)");
}
