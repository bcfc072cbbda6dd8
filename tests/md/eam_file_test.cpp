// The EAM file readers (funcfl, setfl, fs) and their error messages: every shipped file
// read, the setfl tables, a truncated or malformed file named with its line; hostile
// files (issue 17): headers that would wrap or exhaust memory, nan in a file, an empty
// file and a directory.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/eam_file.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;
namespace fs = std::filesystem;

namespace {

using mpmx::test::kCuMishin;
using mpmx::test::kLammpsPotentials;
using mpmx::test::scratch_file;

std::string read_text(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A file's text with line `line` (1-based) replaced.
std::string with_line(const std::string& path, int line, const std::string& text) {
  std::istringstream in(read_text(path));
  std::string out, l;
  for (int n = 1; std::getline(in, l); ++n) out += (n == line ? text : l) + "\n";
  return out;
}

// The Mishin Cu file (setfl) and Debian's Cu_u3.eam (funcfl) with a line replaced.
std::string cu_with_line(int line, const std::string& text) { return with_line(kCuMishin, line, text); }
std::string u3_with_line(int line, const std::string& text) {
  return with_line(kLammpsPotentials + "Cu_u3.eam", line, text);
}

std::string error_of(const std::string& path) {
  try {
    read_eam(path);
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(EamFile, ReadsEveryShippedEamFile) {
  if (!fs::exists(kLammpsPotentials)) GTEST_SKIP() << "lammps-data not installed";
  int n = 0;
  for (const auto& e : fs::directory_iterator(kLammpsPotentials)) {
    const auto name = e.path().filename().string();
    if (!(name.ends_with(".eam") || name.ends_with(".eam.alloy") || name.ends_with(".eam.fs"))) continue;
    EXPECT_NO_THROW(read_eam(e.path().string())) << name;
    ++n;
  }
  EXPECT_GE(n, 10);
}

TEST(EamFile, SetflHeaderAndTables) {
  const auto t = read_eam(kLammpsPotentials + "Cu_mishin1.eam.alloy");
  EXPECT_EQ(t.format, "setfl");
  ASSERT_EQ(t.elements.size(), 1u);
  EXPECT_EQ(t.elements[0], "Cu");
  EXPECT_DOUBLE_EQ(t.masses[0], 63.55);
  EXPECT_EQ(t.nrho, 10001);
  EXPECT_EQ(t.nr, 10001);
  EXPECT_NEAR(t.cut, 5.50679, 1e-12);
  const auto f = read_eam(kLammpsPotentials + "CuZr_mm.eam.fs");
  EXPECT_EQ(f.format, "fs");
  EXPECT_EQ(f.rhor.size(), 4u);
  EXPECT_EQ(f.z2r.size(), 3u);
  const auto u = read_eam(kLammpsPotentials + "Cu_u3.eam");
  EXPECT_EQ(u.format, "funcfl");
  EXPECT_EQ(u.nr, 499);  // LAMMPS's int(rmax/dr + 0.5)
}

TEST(EamFile, TruncatedFileNamesFileLineAndExpectation) {
  const auto text = read_text(kLammpsPotentials + "Cu_mishin1.eam.alloy");
  // Keep the header and a few hundred lines: F(rho) ends early.
  std::size_t pos = 0;
  for (int l = 0; l < 300; ++l) pos = text.find('\n', pos) + 1;
  const auto p = scratch_file("Cu_cut.eam.alloy", text.substr(0, pos));
  const auto msg = error_of(p);
  EXPECT_NE(msg.find("Cu_cut.eam.alloy:300:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("file ends early: expected 10001 values of F(rho) of Cu"), std::string::npos) << msg;
}

TEST(EamFile, BadValuesAreNamed) {
  auto text = read_text(kLammpsPotentials + "Cu_mishin1.eam.alloy");
  // Corrupt a number on line 8.
  std::size_t pos = 0;
  for (int l = 0; l < 7; ++l) pos = text.find('\n', pos) + 1;
  text.insert(pos, "abc ");
  auto msg = error_of(scratch_file("Cu_bad.eam.alloy", text));
  EXPECT_NE(msg.find("Cu_bad.eam.alloy:8: expected a number (F(rho) of Cu), found 'abc'"), std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_hdr.eam.alloy", "a\nb\nc\n2 Cu\n"));
  EXPECT_NE(msg.find("Cu_hdr.eam.alloy:4: expected 2 element names after N, found 1"), std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_grid.eam.alloy", "a\nb\nc\n1 Cu\n100 0.1 x 0.1 5\n"));
  EXPECT_NE(msg.find("Cu_grid.eam.alloy:5: expected an integer (nr), found 'x'"), std::string::npos) << msg;
  msg = error_of(scratch_file("Cu_short.eam", "comment\n29 63.55\n"));
  EXPECT_NE(msg.find("Cu_short.eam:2: file ends early: expected 'nrho drho nr dr cutoff' on line 3"),
            std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu.txt", "x"));
  EXPECT_NE(msg.find("cannot tell the EAM format"), std::string::npos) << msg;
  msg = error_of("/nonexistent/Cu.eam");
  EXPECT_NE(msg.find("/nonexistent/Cu.eam: cannot open"), std::string::npos) << msg;
}

TEST(EamFileHostile, HeaderCountsAboveTheLimitAreRefusedBeforeAllocating) {
  // 2e9 points would be 16 GB a table: refused on the header line with count and limit.
  auto msg = error_of(scratch_file("Cu_2e9.eam.alloy", cu_with_line(5, "2000000000 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_2e9.eam.alloy:5: nrho = 2000000000: out of range: expected from 5 to 10000000 grid "
                     "points"),
            std::string::npos)
      << msg;
  // 1e12 does not fit in 32 bits: before, it wrapped to a negative nrho.
  msg = error_of(scratch_file("Cu_1e12.eam.alloy", cu_with_line(5, "10001 0.0002 1000000000000 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_1e12.eam.alloy:5: nr = 1000000000000: out of range: expected from 5 to 10000000"),
            std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_1e12f.eam.alloy", cu_with_line(5, "1e12 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_1e12f.eam.alloy:5: expected an integer (nrho), found '1e12'"), std::string::npos) << msg;
  msg = error_of(scratch_file("Cu_big64.eam.alloy", cu_with_line(5, "99999999999999999999999 0.1 10001 0.0009 5.5")));
  EXPECT_NE(msg.find(":5: nrho = 99999999999999999999999: out of range"), std::string::npos) << msg;
  msg = error_of(scratch_file("Cu_nel.eam.alloy", cu_with_line(4, "4294967297 Cu")));
  EXPECT_NE(msg.find(":4: number of elements = 4294967297: out of range: expected from 1 to 100 elements"),
            std::string::npos)
      << msg;
}

TEST(EamFileHostile, CountsTheFileCannotHoldAreRefusedOnTheHeader) {
  // Within the limit, but ten times more values than the file has: refused on line 5
  // (not after sizing tables by the claim).
  const auto msg =
      error_of(scratch_file("Cu_claim.eam.alloy", cu_with_line(5, "9000000 0.0002 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_claim.eam.alloy:5: 1 element(s) with nrho = 9000000 and nr = 10001 promise"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("but the rest of the file holds"), std::string::npos) << msg;
}

TEST(EamFileHostile, NanAndInfInTheFileAreRefusedWithTheLine) {
  auto msg = error_of(scratch_file("Cu_nan.eam.alloy", cu_with_line(5, "10001 nan 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_nan.eam.alloy:5: expected a finite number (drho), found 'nan'"), std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_inf.eam.alloy", cu_with_line(8, "inf 1 2 3 4")));
  EXPECT_NE(msg.find("Cu_inf.eam.alloy:8: expected a finite number (F(rho) of Cu), found 'inf'"),
            std::string::npos)
      << msg;
}

TEST(EamFileHostile, EmptyFileAndDirectoryAreNamed) {
  auto msg = error_of(scratch_file("Empty.eam.alloy", ""));
  EXPECT_NE(msg.find("Empty.eam.alloy: the EAM potential file is empty"), std::string::npos) << msg;
  const auto dir = mpmx::test::scratch_root() / "Dir.eam.alloy";
  std::filesystem::create_directories(dir);
  msg = error_of(dir.string());
  EXPECT_NE(msg.find("Dir.eam.alloy: is a directory"), std::string::npos) << msg;
}

// Tables that parse but describe no potential (issue 45): refused on the header line with
// the value and the reason, not run (dr = 1e-300 ran with no interaction at all, drho =
// 1e300 gave -1.20 eV/atom for -3.54, mass = 1e-300 an infinite temperature).
TEST(EamFileDamaged, TablesThatEndBeforeTheCutoffAreRefused) {
  auto msg = error_of(scratch_file("u3_dr.eam", u3_with_line(3, "500 5.01e-04 500 1e-300 4.95")));
  EXPECT_NE(msg.find("u3_dr.eam:3: nr * dr = 500 * 1e-300 = 5e-298 A ends before the cutoff 4.95 A"),
            std::string::npos)
      << msg;
  // One interval short of the cutoff (LAMMPS's files reach it exactly or beyond).
  msg = error_of(scratch_file("u3_short.eam", u3_with_line(3, "500 5.01e-04 500 0.0098 4.95")));
  EXPECT_NE(msg.find("u3_short.eam:3: nr * dr = 500 * 0.0098 = 4.9 A ends before the cutoff 4.95 A"),
            std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_dr.eam.alloy", cu_with_line(5, "10001 0.000164 10001 0.0001 5.50679")));
  EXPECT_NE(msg.find("Cu_dr.eam.alloy:5: nr * dr = 10001 * 0.0001 = 1.0001 A ends before the cutoff 5.50679 A"),
            std::string::npos)
      << msg;
}

TEST(EamFileDamaged, DegenerateSpacingsAreRefused) {
  // Five intervals below the cutoff: nothing is tabulated.
  auto msg = error_of(scratch_file("u3_coarse.eam", u3_with_line(3, "500 5.01e-04 500 1.0 4.95")));
  EXPECT_NE(msg.find("u3_coarse.eam:3: dr = 1 A leaves 4.95 grid intervals below the cutoff 4.95 A: at least 10"),
            std::string::npos)
      << msg;
  msg = error_of(scratch_file("u3_drho.eam", u3_with_line(3, "500 1e300 500 0.01 4.95")));
  EXPECT_NE(msg.find("u3_drho.eam:3: drho = 1e+300 is coarser than the largest density one neighbour brings "
                     "beyond 1 A"),
            std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_drho.eam.alloy", cu_with_line(5, "10001 1e300 10001 0.0009 5.50679")));
  EXPECT_NE(msg.find("Cu_drho.eam.alloy:5: drho = 1e+300 is coarser"), std::string::npos) << msg;
  // Finnis-Sinclair: every rho_ij(r) table counts (CuZr_mm's header, drho changed).
  const std::string fs_text =
      with_line(kLammpsPotentials + "CuZr_mm.eam.fs", 5, "10000 1e300 10000 0.00076 7.6");
  msg = error_of(scratch_file("CuZr_drho.eam.fs", fs_text));
  EXPECT_NE(msg.find("CuZr_drho.eam.fs:5: drho = 1e+300 is coarser"), std::string::npos) << msg;
}

TEST(EamFileDamaged, MassesOutsideAnAtomsAreRefused) {
  auto msg = error_of(scratch_file("u3_mass.eam", u3_with_line(2, "29 1e-300 3.615 FCC")));
  EXPECT_NE(msg.find("u3_mass.eam:2: mass = 1e-300 amu: an atom's mass lies in [0.5, 1000] amu"), std::string::npos)
      << msg;
  msg = error_of(scratch_file("Cu_mass.eam.alloy", cu_with_line(6, "29 5000 3.615 fcc")));
  EXPECT_NE(msg.find("Cu_mass.eam.alloy:6: mass = 5000 amu of element Cu: an atom's mass lies in [0.5, 1000]"),
            std::string::npos)
      << msg;
  // The bounds themselves are an atom's.
  EXPECT_NO_THROW(read_eam(scratch_file("u3_light.eam", u3_with_line(2, "1 0.5 3.615 FCC"))));
  EXPECT_NO_THROW(read_eam(scratch_file("u3_heavy.eam", u3_with_line(2, "29 1000 3.615 FCC"))));
}
