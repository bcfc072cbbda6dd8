// Paths and files that cannot be used are bad input (exit 2) said in a sentence, never a
// library's message: an output folder that cannot be made (read-only, a name too long), a
// deck path beyond the system's limit, a folder given as a potential file, a potential
// file of garbage (quoted short and printable); and a comparison where the exact solution
// passes through zero is measured against the solution's size over the run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli_util.hpp"
#include "md/md_test_util.hpp"
#include "mpm/mpm_test_util.hpp"
#include "mpmx/core/exit_codes.hpp"
#include "mpmx/core/file_text.hpp"

namespace {

using namespace mpmx;
namespace fs = std::filesystem;

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

std::string a1() { return test::example("A1_standing_wave_moving.toml"); }

bool printable(const std::string& s) {
  for (const char c : s)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || static_cast<unsigned char>(c) >= 0x7f)
      return false;
  return true;
}

// A small EAM copper MD deck naming `file` as its potential (found beside the deck).
fs::path md_deck_with_potential(const std::string& file) {
  return test::scratch_file("md_" + file + ".toml", "[potential]\nstyle = \"eam\"\nfile = \"" + file +
                                                         "\"\nelements = [\"Cu\"]\n[lattice]\nconstant = 3.615\n"
                                                         "cells = [3, 3, 3]\n[run]\ndt = 0.001\nsteps = 1\n");
}

TEST(FileMessages, OutputFolderThatCannotBeMadeIsBadInput) {
  // /proc takes no new folders, for any user.
  const auto r = test::run_cli("run " + a1() + " --quiet --no-plot --out /proc/mpmx_no_such/out");
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_HAS(r.output, "--out /proc/mpmx_no_such/out: cannot make the output folder");
  EXPECT_EQ(r.output.find("filesystem error"), std::string::npos) << r.output;
}

TEST(FileMessages, OutputFolderNameTooLongIsBadInput) {
  const std::string name = (test::scratch_root() / std::string(300, 'a')).string();
  fs::create_directories(test::scratch_root());
  for (const std::string& cmd : {"run " + a1() + " --quiet --no-plot", "dpd " + test::example("D_dpd_equilibrium.toml")}) {
    const auto r = test::run_cli(cmd + " --out " + name);
    EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
    EXPECT_HAS(r.output, "has a name of 300 bytes in it, more than the 255");
    EXPECT_EQ(r.output.find("filesystem error"), std::string::npos) << r.output;
  }
}

TEST(FileMessages, DeckPathBeyondTheSystemLimitSaysSo) {
  // A 5,000-character path to an existing deck: "./" repeated.
  std::string path;
  while (path.size() + a1().size() < 5000) path += "./";
  path = fs::path(a1()).parent_path().string() + "/" + path + fs::path(a1()).filename().string();
  for (const char* cmd : {"check ", "run ", "md ", "dpd "}) {
    const auto r = test::run_cli(std::string(cmd) + path);
    EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
    EXPECT_HAS(r.output, "characters long, more than the system's limit of 4095");
    EXPECT_EQ(r.output.find("File does not exist"), std::string::npos) << r.output;
    EXPECT_LT(r.output.size(), 1000u);  // the path is shortened in the message
  }
}

TEST(FileMessages, FolderAsPotentialFileSaysItIsAFolder) {
  fs::create_directories(test::scratch_root() / "Folder.eam.alloy");
  const auto deck = md_deck_with_potential("Folder.eam.alloy");
  const auto r = test::run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_HAS(r.output, "is a directory, not a potential file");
  EXPECT_EQ(r.output.find("not found"), std::string::npos) << r.output;
}

TEST(FileMessages, FolderAsDpdPotentialFileSaysItIsAFolder) {
  fs::create_directories(test::scratch_root() / "folder_potential.toml");
  const auto deck = test::scratch_file("dpd_folder_potential.toml",
                                       "[case]\nid = \"d\"\n[potential]\nfile = \"folder_potential.toml\"\n"
                                       "[[block]]\nconstant = 7.23\ncells = [2, 2, 2]\nmass = 1.0\n[dpd]\ngamma = 0.2\n"
                                       "temperature = 1.0\n[run]\ndt = 0.005\nsteps = 1\n");
  const auto r = test::run_cli("dpd " + deck.string() + " --check");
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_HAS(r.output, "is a directory, not a potential file");
}

TEST(FileMessages, GarbagePotentialFileIsQuotedShortAndPrintable) {
  std::string junk = "comment 1\ncomment 2\ncomment 3\n1 Cu\n";
  for (int i = 0; i < 600; ++i) junk += static_cast<char>(i % 256 == 10 ? 1 : i % 256);
  junk += "\n";
  std::ofstream(test::scratch_root() / "Junk.eam.alloy", std::ios::binary) << junk;
  const auto deck = md_deck_with_potential("Junk.eam.alloy");
  const auto r = test::run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_TRUE(printable(r.output)) << r.output;
  EXPECT_LT(r.output.size(), 600u) << r.output;
}

TEST(FileMessages, QuoteExcerptEscapesAndCuts) {
  EXPECT_EQ(quote_excerpt("ab\x01", 40), "'ab\\x01'");
  EXPECT_EQ(quote_excerpt(std::string(100, 'x'), 4), "'xxxx'... (100 bytes)");
}

// Text a user gave is shown, never obeyed (issue 45): control characters and NUL in a
// deck's strings, keys and paths are escaped in every message and progress line, and a
// NUL no longer cuts a message short.
TEST(FileMessages, EscapeControlsEscapesControlCharactersOnly) {
  EXPECT_EQ(escape_controls(std::string("a\x1b[2J\0b\n\t\x7f", 10)), "a\\x1b[2J\\x00b\\x0a\\x09\\x7f");
  EXPECT_EQ(escape_controls("line\n\tnext", true), "line\n\tnext");
  EXPECT_EQ(escape_controls("Kupfer \xc3\xa9 \xe2\x84\xab"), "Kupfer \xc3\xa9 \xe2\x84\xab");  // UTF-8 stays
  EXPECT_EQ(short_path(std::string("a\0b", 3)), "a\\x00b");
}

TEST(FileMessages, ControlCharactersInACaseIdAreEscaped) {
  std::ifstream in(a1());
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text.replace(text.find("id = \"A1\""), 9, "id = \"A1\\u001b[31mRED\\u0000x\\ny\"");
  const auto deck = test::scratch_file("esc_id.toml", text);
  auto r = test::run_cli("check " + deck.string());
  EXPECT_EQ(r.status, exit_code::done) << r.output;
  EXPECT_HAS(r.output, "case A1\\x1b[31mRED\\x00x\\x0ay,");
  EXPECT_TRUE(printable(r.output)) << r.output;
  // A key written with control characters, named in the unknown-key message.
  text.replace(text.find("[case]"), 6, "[case]\n\"k\\u001b]0;title\\u0007\" = 1");
  r = test::run_cli("check " + test::scratch_file("esc_key.toml", text).string());
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_HAS(r.output, "k\\x1b]0;title\\x07");
  EXPECT_TRUE(printable(r.output)) << r.output;
}

TEST(FileMessages, ANulInAPotentialFileNameDoesNotCutTheMessage) {
  const auto deck = test::scratch_file("nul_file.toml", "[potential]\nstyle = \"eam\"\nfile = \"Cu\\u0000.eam\\u001b[2J\"\n"
                                                        "[lattice]\nconstant = 3.615\ncells = [3, 3, 3]\n[run]\n"
                                                        "dt = 0.001\nsteps = 1\n");
  const auto r = test::run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, exit_code::bad_input) << r.output;
  EXPECT_HAS(r.output, "potential file 'Cu\\x00.eam\\x1b[2J' not found (tried: ");
  EXPECT_TRUE(printable(r.output)) << r.output;
}

// The standing wave's velocity is zero everywhere at t = 0.5 and its strain at t = 1: the
// errors there are against the wave's size over the run, not against rounding (1e16).
TEST(FileMessages, ErrorWhereTheSolutionIsZeroIsScaledByTheRun) {
  const auto c = test::deck_with(a1(), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 1.0);
    t["output"].as_table()->insert_or_assign("times", toml::array{0.5, 1.0});
    t["reference"].as_table()->insert_or_assign("times", toml::array{0.25, 0.5, 1.0});
  });
  const auto r = test::run(c);
  for (const auto& [field, e] : r.errors) {
    EXPECT_LT(e.l1, 0.1) << field;
    EXPECT_LT(e.l2, 0.1) << field;
    EXPECT_LT(e.peak, 0.1) << field;
  }
  EXPECT_EQ(r.errors.count("velocity"), 1u);
  EXPECT_EQ(r.errors.count("strain"), 1u);
}

}  // namespace
