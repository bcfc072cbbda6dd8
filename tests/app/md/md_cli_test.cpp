// `mpmx md DECK --out DIR`: run.json names, thermo CSV, and deck errors that name the
// key, the value and the reason (exit status 2); hostile input (issue 17): the checks
// `--check` shares with the run, no output folder left by a refused run, memory and work
// estimates, and a run the physics stopped (exit status 3) still leaving valid JSON.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "../../md/md_test_util.hpp"
#include "../../io/strict_json.hpp"
#include "cli_util.hpp"


namespace fs = std::filesystem;

namespace {
using mpmx::test::json_number;
using mpmx::test::run_cli;
using mpmx::test::slurp;
using Result = mpmx::test::CliResult;


fs::path write_deck(const std::string& name, const std::string& text) {
  return mpmx::test::scratch_file(name, text);
}

fs::path deck_dir() { return mpmx::test::scratch_root(); }

const std::string kGoodMdDeck = R"(
[potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.615
cells = [3, 3, 3]
[thermal]
temperature = 300.0
seed = 4
[run]
dt = 0.001
steps = 40
thermo = 10
dump_every = 20
strain_rate_per_s = 1e9
)";

}  // namespace

// The numbers of a JSON array value (nested arrays flattened), up to its closing bracket.
std::vector<double> json_numbers(const std::string& json, const std::string& key) {
  std::vector<double> out;
  const std::string tag = "\"" + key + "\" : ";
  auto at = json.find(tag);
  if (at == std::string::npos) return out;
  int depth = 0;
  for (std::size_t i = at + tag.size(); i < json.size(); ++i) {
    const char c = json[i];
    if (c == '[') ++depth;
    else if (c == ']') { if (--depth == 0) break; }
    else if (c == '-' || c == '+' || (c >= '0' && c <= '9')) {
      char* end = nullptr;
      out.push_back(std::strtod(json.c_str() + i, &end));
      i = static_cast<std::size_t>(end - json.c_str()) - 1;
    }
  }
  return out;
}

TEST(MdCli, RunWritesRunJsonAndThermo) {
  const auto deck = write_deck("good.toml", kGoodMdDeck);
  const auto out = deck.parent_path() / "out_good";
  fs::remove_all(out);
  const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = slurp(out / "run.json");
  EXPECT_EQ(json_number(json, "atoms"), 108);
  EXPECT_EQ(json_number(json, "steps"), 40);
  EXPECT_GT(json_number(json, "wall_seconds"), 0);
  EXPECT_GT(json_number(json, "atom_steps_per_second"), 0);
  EXPECT_NEAR(json_number(json, "potential_energy_per_atom"), -3.5, 0.05);
  // stress_gpa: a 3x3 array of numbers.
  EXPECT_EQ(json_numbers(json, "stress_gpa").size(), 9u) << json;
  EXPECT_NE(json.find("\"deck\""), std::string::npos);
  EXPECT_NE(json.find("\"status\" : \"completed\""), std::string::npos) << json;
  EXPECT_EQ(json.find("non_finite"), std::string::npos) << json;
  mpmx::test::StrictJson strict(json);
  EXPECT_TRUE(strict.valid()) << strict.error();
  const std::string csv = slurp(out / "thermo.csv");
  EXPECT_EQ(csv.rfind("step,time_ps,pe_per_atom_eV", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 5);  // header + steps 0,10,20,30,40
  const std::string dump = slurp(out / "dump.lammpstrj");
  std::size_t frames = 0;
  for (std::size_t p = dump.find("ITEM: TIMESTEP"); p != std::string::npos; p = dump.find("ITEM: TIMESTEP", p + 1))
    ++frames;
  EXPECT_EQ(frames, 3u);  // steps 0, 20, 40
  EXPECT_NE(dump.find("ITEM: ATOMS id type x y z vx vy vz"), std::string::npos);
}

TEST(MdCli, CheckValidatesOnly) {
  const auto deck = write_deck("check.toml", kGoodMdDeck);
  const auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos);
}

// An oriented crystal's check states its periodic tile and box (M6).
TEST(MdCli, CheckStatesTheOrientedTile) {
  const auto r = run_cli(std::string("md ") + MPMX_SOURCE_DIR + "/examples/M6_fe_bcc_110.toml --check");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("lattice: bcc a = 2.85532 A, x [1,1,0] y [-1,1,0] z [0,0,1]: periodic tile 4.03803 x "
                          "4.03803 x 2.85532 A of 4 atoms; box 6 x 6 x 8 tiles = 24.2282 x 24.2282 x 22.8426 A, 1152 "
                          "atoms"),
            std::string::npos)
      << r.output;
}

// A [jet] and a [rod] of an oriented lattice: check states the tile their counts count.
TEST(MdCli, CheckStatesTheTileOfAJetAndARod) {
  const std::string head = "[potential]\nfile = \"" + mpmx::test::kLammpsPotentials +
                           "Fe_mm.eam.fs\"\nelements = [\"Fe\"]\n[lattice]\ntype = \"bcc\"\nconstant = 2.8553\n"
                           "orient = [[1, 1, 0], [-1, 1, 0], [0, 0, 1]]\ncells = [1, 1, 1]\n[run]\ndt = 0.001\n";
  auto r = run_cli("md " + write_deck("jet_bcc.toml", head + "[jet]\ncells = [16, 8, 3]\npiston_cells = 2\n"
                                                             "notch_depth_nm = 0.5\nbins = [8, 2]\n"
                                                             "duration_ps = 0.02\nrecord_every_ps = 0.01\n")
                             .string() +
                   " --check");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("lattice: bcc a = 2.8553 A, x [1,1,0] y [-1,1,0] z [0,0,1]: periodic tile 4.038 x 4.038 x "
                          "2.8553 A of 4 atoms; jet (scale 1, piston 2 tiles; before the notch) 16 x 8 x 3 tiles = "
                          "64.6081 x 32.304 x 8.5659 A, 1536 atoms"),
            std::string::npos)
      << r.output;
  r = run_cli("md " + write_deck("rod_bcc.toml", head + "steps = 10\n[rod]\ntarget_cells = [6, 2, 2]\n"
                                                        "flyer_cells = 2\nflyer_velocity = 5.0\nrescale_every = 0\n")
                          .string() +
              " --check");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("periodic tile 4.038 x 4.038 x 2.8553 A of 4 atoms; rod (flyer 2 + target 6 tiles along "
                          "x) 8 x 2 x 2 tiles = 32.304 x 8.07601 x 5.7106 A, 128 atoms"),
            std::string::npos)
      << r.output;
}

TEST(MdCli, BadDeckNamesKeyValueReason) {
  std::string text = kGoodMdDeck;
  text.replace(text.find("dt = 0.001"), 10, "dt = -0.5");
  text.replace(text.find("cells = [3, 3, 3]"), 17, "cells = [3, 0, 3]\nwidth = 2");
  text.replace(text.find("Cu_mishin1.eam.alloy"), 20, "Nope.eam.alloy");
  const auto deck = write_deck("bad.toml", text);
  const auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("run.dt"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-0.5"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lattice.cells"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("lattice.width"), std::string::npos) << r.output;  // unknown key
  EXPECT_NE(r.output.find("potential file 'Nope.eam.alloy' not found"), std::string::npos) << r.output;
}

TEST(MdCli, MalformedPotentialFileIsAnInputError) {
  const auto pot = write_deck("Broken.eam.alloy", "c\nc\nc\n1 Cu\n100 0.01 100 0.01 5.0\n29 63.55 3.6 fcc\n1 2 3\n");
  std::string text = kGoodMdDeck;
  text.replace(text.find("Cu_mishin1.eam.alloy"), 20, "Broken.eam.alloy");
  const auto deck = write_deck("broken.toml", text);
  const auto r = run_cli("md " + deck.string() + " --out " + (deck.parent_path() / "out_broken").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("Broken.eam.alloy:7: file ends early: expected 100 values of F(rho) of Cu, found 3"),
            std::string::npos)
      << r.output;
}

TEST(MdCli, BenchAndExampleDecksAreValid) {
  for (const char* d : {"bench/md_cu500.toml", "bench/md_cu32000.toml", "examples/MD_bar_release.toml"}) {
    const auto r = run_cli(std::string("md ") + MPMX_SOURCE_DIR + "/" + d + " --check");
    EXPECT_EQ(r.status, 0) << d << r.output;
  }
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(MPMX_SOURCE_DIR) / "examples")) {
    const auto name = e.path().filename().string();
    if (name.size() < 3 || name[0] != 'M' || !std::isdigit(static_cast<unsigned char>(name[1]))) continue;
    const auto r = run_cli("md " + e.path().string() + " --check");
    EXPECT_EQ(r.status, 0) << name << r.output;
    ++n;
  }
  EXPECT_GE(n, 5);
}

// The good deck less what only its periodic box uses (a [bar] refuses them).
std::string bar_run() {
  std::string text = kGoodMdDeck;
  for (const std::string line : {"dump_every = 20\n", "strain_rate_per_s = 1e9\n"}) text.erase(text.find(line), line.size());
  return text;
}

TEST(MdCli, BarDeckWritesBinnedStressOverTime) {
  std::string text = bar_run();
  text += "[bar]\ncells_x = 8\ncells_yz = 2\nstrain_left = -0.01\nbins = 8\noutput_every = 20\n";
  const auto deck = write_deck("bar.toml", text);
  const auto out = deck.parent_path() / "out_bar";
  fs::remove_all(out);
  const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string csv = slurp(out / "bar_stress.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 3 * 8);  // steps 0, 20, 40 x 8 bins
  EXPECT_EQ(json_number(slurp(out / "run.json"), "atoms"), 128);
}

// One large system on two threads: the same binned stress, to the last digit written,
// as on one (2304 atoms: two tiles).
TEST(MdCli, ThreadsGiveTheSameRun) {
  std::string text = bar_run();
  text += "[bar]\ncells_x = 144\ncells_yz = 2\nstrain_left = -0.01\nbins = 8\noutput_every = 20\n";
  const auto deck = write_deck("bar_threads.toml", text);
  std::string csv[2];
  for (const int n : {1, 2}) {
    const auto out = deck.parent_path() / ("out_bar_threads_" + std::to_string(n));
    fs::remove_all(out);
    const auto r =
        run_cli("md " + deck.string() + " --out " + out.string() + " --quiet --threads " + std::to_string(n));
    ASSERT_EQ(r.status, 0) << r.output;
    csv[n - 1] = slurp(out / "bar_stress.csv");
  }
  EXPECT_GT(csv[0].size(), 100u);
  EXPECT_EQ(csv[0], csv[1]);
}

// ------------------------------------------------ hostile input (issue 17)

namespace {

std::string with(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

bool strict_json(const std::string& text, std::string& why) {
  mpmx::test::StrictJson j(text);
  const bool ok = j.valid();
  why = j.error();
  return ok;
}

}  // namespace

TEST(MdCliHostile, CheckParsesThePotentialFile) {
  write_deck("Empty.eam.alloy", "");
  const auto deck = write_deck("empty_pot.toml", with(kGoodMdDeck, "Cu_mishin1.eam.alloy", "Empty.eam.alloy"));
  const auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("Empty.eam.alloy: the EAM potential file is empty"), std::string::npos) << r.output;
}

TEST(MdCliHostile, CheckRefusesAnElementTheFileLacks) {
  const auto deck = write_deck("no_zr.toml", with(kGoodMdDeck, "elements = [\"Cu\"]", "elements = [\"Zr\"]"));
  const auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("key 'potential.elements' = [\"Zr\"]: element 'Zr' is not in"), std::string::npos)
      << r.output;
}

TEST(MdCliHostile, BadPotentialLeavesNoOutputDirectory) {
  write_deck("Header.eam.alloy", "c\nc\nc\n1 Cu\n2000000000 0.01 100 0.01 5.0\n29 63.55 3.6 fcc\n1 2 3\n");
  for (const std::string pot : {"Header.eam.alloy", "Broken.eam.alloy", "Missing.eam.alloy"}) {
    if (pot == "Broken.eam.alloy")
      write_deck(pot, "c\nc\nc\n1 Cu\n100 0.01 100 0.01 5.0\n29 63.55 3.6 fcc\n1 2 3\n");
    const auto deck = write_deck("leave_" + pot + ".toml", with(kGoodMdDeck, "Cu_mishin1.eam.alloy", pot));
    const auto out = deck.parent_path() / ("out_leave_" + pot);
    fs::remove_all(out);
    const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
    EXPECT_EQ(r.status, 2) << pot << r.output;
    EXPECT_FALSE(fs::exists(out)) << pot << ": " << out << " left behind";
  }
  const auto r = run_cli("md " + (deck_dir() / "leave_Header.eam.alloy.toml").string());
  EXPECT_NE(r.output.find("Header.eam.alloy:5: nrho = 2000000000: out of range: expected from 5 to 10000000"),
            std::string::npos)
      << r.output;
}

TEST(MdCliHostile, DirectoryAsDeckIsNamed) {
  fs::create_directories(deck_dir());
  const auto r = run_cli("md " + deck_dir().string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("is a directory, not a deck file"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("is missing"), std::string::npos) << r.output;
}

TEST(MdCliHostile, NanVelocityGradientRefusedAtCheck) {
  const auto deck = write_deck("nan_grad.toml", with(kGoodMdDeck, "strain_rate_per_s = 1e9",
                                                     "velocity_gradient_per_ps = [0,0,0, 0,nan,0, 0,0,0]"));
  const auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("key 'run.velocity_gradient_per_ps'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("entry 5 is nan"), std::string::npos) << r.output;
}

TEST(MdCliHostile, HugeLatticeRefusedForMemoryEvenWithForce) {
  const auto deck = write_deck("huge.toml", with(kGoodMdDeck, "cells = [3, 3, 3]", "cells = [1000, 1000, 1000]"));
  for (const char* flags : {" --check", " --check --force", " --force --quiet --out /nonexistent/never"}) {
    const auto r = run_cli("md " + deck.string() + flags);
    EXPECT_EQ(r.status, 2) << flags << r.output;
    EXPECT_NE(r.output.find("lattice.cells: 4e+09 atoms need about"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("bytes), more than this machine's"), std::string::npos) << r.output;
  }
}

TEST(MdCliHostile, WorkAboveADayRefusedUnlessForced) {
  const auto deck = write_deck("long.toml", with(kGoodMdDeck, "steps = 40", "steps = 9000000000000"));
  auto r = run_cli("md " + deck.string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("run.steps: 108 atoms x 9e+12 steps = 9.72e+14 atom-steps"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
  r = run_cli("md " + deck.string() + " --check --force");
  EXPECT_EQ(r.status, 0) << r.output;
}

TEST(MdCliHostile, RunThatGoesNonFiniteStopsWithValidJson) {
  // The box doubles along x every step: inf after about 1,100 steps.
  std::string text =
      with(kGoodMdDeck, "strain_rate_per_s = 1e9", "velocity_gradient_per_ps = [1000,0,0, 0,0,0, 0,0,0]");
  text = with(text, "steps = 40", "steps = 3000");
  text = with(text, "thermo = 10", "thermo = 100");
  text = with(text, "dump_every = 20", "dump_every = 0");
  const auto deck = write_deck("blow.toml", text);
  const auto out = deck.parent_path() / "out_blow";
  fs::remove_all(out);
  const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
  EXPECT_EQ(r.status, 3) << r.output;  // stopped by the physics, partial result written
  EXPECT_NE(r.output.find("went non-finite"), std::string::npos) << r.output;
  const std::string json = slurp(out / "run.json");
  std::string why;
  EXPECT_TRUE(strict_json(json, why)) << why << "\n" << json;
  EXPECT_NE(json.find("\"status\" : \"stopped\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"non_finite\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"box.lx\""), std::string::npos) << json;
  // The top-level step count (the deck echo's "steps" comes first): the steps done.
  const auto at = json.find("\n    \"steps\" : ");
  ASSERT_NE(at, std::string::npos) << json;
  const long done = std::strtol(json.c_str() + at + 15, nullptr, 10);
  EXPECT_GT(done, 0) << json;
  EXPECT_LT(done, 3000) << json;
}

TEST(MdCliHostile, OutThatIsAFileIsBadInput) {
  const auto deck = write_deck("out_file.toml", kGoodMdDeck);
  const auto file = write_deck("not_a_dir.txt", "x");
  const auto r = run_cli("md " + deck.string() + " --quiet --out " + file.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("exists and is not a directory"), std::string::npos) << r.output;
}

// ------------------------------------------------ per-atom output (issue 47)

namespace {

// The last frame of a dump: its column names and rows.
struct Frame {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  int column(const std::string& n) const {
    return static_cast<int>(std::find(names.begin(), names.end(), n) - names.begin());
  }
  double mean(const std::string& n) const {
    double s = 0;
    for (const auto& r : rows) s += r[column(n)];
    return s / static_cast<double>(rows.size());
  }
};

Frame last_frame(const std::string& dump) {
  Frame f;
  const auto at = dump.rfind("ITEM: ATOMS ");
  std::istringstream in(dump.substr(at + 12));
  std::string header;
  std::getline(in, header);
  std::istringstream h(header);
  for (std::string n; h >> n;) f.names.push_back(n);
  for (std::string line; std::getline(in, line);) {
    std::istringstream l(line);
    std::vector<double> row;
    for (double v; l >> v;) row.push_back(v);
    if (row.size() == f.names.size()) f.rows.push_back(row);
  }
  return f;
}

}  // namespace

// Per-atom energy and stress average to the box's (thermo.csv at the same step), and a
// copper crystal at 300 K is fcc atom by atom.
TEST(MdCli, DumpFieldsAverageToTheBoxAndNameTheCrystal) {
  const auto deck = write_deck("fields.toml", with(kGoodMdDeck, "dump_every = 20",
                                                   "dump_every = 20\ndump_fields = [\"pe\", \"stress\", \"structure\"]"));
  const auto out = deck.parent_path() / "out_fields";
  fs::remove_all(out);
  const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string dump = slurp(out / "dump.lammpstrj");
  EXPECT_NE(dump.find("ITEM: ATOMS id type x y z vx vy vz pe sxx syy szz sxy sxz syz structure"), std::string::npos);
  const Frame f = last_frame(dump);
  ASSERT_EQ(f.rows.size(), 108u);
  // thermo.csv's last row (step 40): pe per atom, then sxx .. syz in GPa.
  const std::string csv = slurp(out / "thermo.csv");
  std::istringstream rows(csv);
  std::string line, last;
  while (std::getline(rows, line)) last = line.empty() ? last : line;
  std::vector<double> t;
  std::istringstream cells(last);
  for (std::string c; std::getline(cells, c, ',');) t.push_back(std::stod(c));
  ASSERT_EQ(t[0], 40);
  EXPECT_NEAR(f.mean("pe"), t[2], 1e-8 * std::abs(t[2]));
  const char* names[6] = {"sxx", "syy", "szz", "sxy", "sxz", "syz"};
  for (int c = 0; c < 6; ++c) EXPECT_NEAR(f.mean(names[c]), t[6 + c], 1e-6) << names[c];
  int fcc = 0;
  for (const auto& row : f.rows) fcc += row[f.column("structure")] == 1;
  EXPECT_EQ(fcc, 108);
}

TEST(MdCli, DumpFieldsAreChecked) {
  auto r = run_cli("md " + write_deck("badfield.toml", with(kGoodMdDeck, "dump_every = 20",
                                                            "dump_every = 20\ndump_fields = [\"stres\"]")).string() +
                   " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("run.dump_fields"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'stres' is not a per-atom field"), std::string::npos) << r.output;
  r = run_cli("md " + write_deck("nodump.toml", with(kGoodMdDeck, "dump_every = 20",
                                                     "dump_fields = [\"pe\"]")).string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("needs dump_every > 0"), std::string::npos) << r.output;
}

// ------------------------------------------------ nvt, npt, nph (issue 47)

TEST(MdCli, NptDeckRunsAndSaysItsLatticeConstant) {
  std::string text = with(kGoodMdDeck, "strain_rate_per_s = 1e9", "ensemble = \"npt\"\npressure_gpa = 0.0");
  text = with(text, "steps = 40", "steps = 200");
  const auto deck = write_deck("npt.toml", text);
  const auto out = deck.parent_path() / "out_npt";
  fs::remove_all(out);
  const auto r = run_cli("md " + deck.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = slurp(out / "run.json");
  EXPECT_NE(json.find("\"ensemble\" : \"npt\""), std::string::npos) << json;
  const auto a = json_numbers(json, "lattice_constant_A");
  ASSERT_EQ(a.size(), 3u);
  EXPECT_NE(a[0], 3.615);  // the barostat moved the box
  EXPECT_EQ(a[0], a[1]);
}

TEST(MdCli, EnsembleKeysAreChecked) {
  const auto check = [](const std::string& name, const std::string& from, const std::string& to) {
    return run_cli("md " + write_deck(name, with(kGoodMdDeck, from, to)).string() + " --check");
  };
  auto r = check("nvt_gradient.toml", "dump_every = 20", "dump_every = 20\nensemble = \"nvt\"");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("a thermostat or barostat runs an undeformed box"), std::string::npos) << r.output;
  r = check("nvt_pressure.toml", "strain_rate_per_s = 1e9", "ensemble = \"nvt\"\npressure_gpa = 1.0");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("run.pressure_gpa"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("has no use with ensemble = \"nvt\""), std::string::npos) << r.output;
  r = run_cli("md " + write_deck("npt_cold.toml", with(with(kGoodMdDeck, "temperature = 300.0", "temperature = 0.0"),
                                                       "strain_rate_per_s = 1e9", "ensemble = \"npt\""))
                          .string() +
              " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("key 'run.ensemble' = \"npt\": needs thermal.temperature > 0, not 0 K"), std::string::npos)
      << r.output;
  r = check("npt_axes.toml", "strain_rate_per_s = 1e9", "ensemble = \"npt\"\nbarostat = \"aniso\"\npressure_gpa = [1, 2]");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("[px, py, pz]"), std::string::npos) << r.output;
}

// `check` and the run agree on every ensemble deck: each refuses it with the same
// message (key, value, reason; exit 2) and the run leaves no folder. Before, `check`
// passed nph at 0 K (the run then stopped on a non-finite state) and an npt [bar] (whose
// run wrote its nve twin's bytes).
TEST(MdCli, CheckAndTheRunRefuseTheSameEnsembleDecks) {
  const std::string box = with(kGoodMdDeck, "strain_rate_per_s = 1e9\n", "");
  const std::string cold = with(box, "temperature = 300.0", "temperature = 0.0");
  const std::string bar = "[bar]\ncells_x = 10\ncells_yz = 3\n";
  const std::string bar_box = with(box, "dump_every = 20\n", "");  // a bar writes no dump frames
  const std::string rod = "[rod]\ntarget_cells = [4, 4, 4]\nflyer_cells = 2\nflyer_velocity = 5.0\n";
  const std::vector<std::pair<std::string, std::string>> decks{
      {"ens_nph_cold", cold + "ensemble = \"nph\"\n"},
      {"ens_nvt_cold", cold + "ensemble = \"nvt\"\n"},
      {"ens_nphug_cold", cold + "ensemble = \"nphug\"\npressure_gpa = 10.0\n"},
      {"ens_bar_npt", bar_box + "ensemble = \"npt\"\n" + bar},
      {"ens_bar_nvt_keys", bar_box + "ensemble = \"nvt\"\nt_damp_ps = 0.1\n" + bar},
      {"ens_rod_nvt", box + "ensemble = \"nvt\"\n" + rod},
      {"ens_misspelt", box + "ensemble = \"nphugg\"\npressure_gpa = 1.0\nshock_axis = \"x\"\n"},
      {"ens_short_period", box + "ensemble = \"nvt\"\nt_damp_ps = 0.0001\n"},
  };
  for (const auto& [name, text] : decks) {
    const auto deck = write_deck(name + ".toml", text);
    const auto out = deck.parent_path() / ("out_" + name);
    fs::remove_all(out);
    const auto checked = run_cli("md " + deck.string() + " --check");
    const auto run = run_cli("md " + deck.string() + " --quiet --out " + out.string());
    EXPECT_EQ(checked.status, 2) << name << ": " << checked.output;
    EXPECT_EQ(run.status, 2) << name << ": " << run.output;
    EXPECT_EQ(checked.output, run.output) << name;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 2) << name << ": one error: " << run.output;
    EXPECT_NE(run.output.find("key 'run."), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out)) << name;
  }
}
