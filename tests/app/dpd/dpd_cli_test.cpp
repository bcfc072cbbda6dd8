// `mpmx dpd DECK --out DIR [--threads N] [--check]`: deck errors name the key, the value
// and the reason (exit status 2, nothing written); a run writes run.json, thermo.csv and
// the LAMMPS dump; --threads 2 writes the same thermo table as --threads 1; rigid
// groups and the Berendsen equilibration from the deck; --still starts them at rest.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include "cli_util.hpp"

namespace {
using mpmx::test::run_cli;
using mpmx::test::slurp;
using Result = mpmx::test::CliResult;


namespace fs = std::filesystem;

const fs::path& dir() {
  static const struct D {
    fs::path p = fs::temp_directory_path() / ("mpmx_dpd_cli_" + std::to_string(getpid()));
    D() { fs::create_directories(p); }
    ~D() {
      std::error_code ec;
      fs::remove_all(p, ec);
    }
  } d;
  return d.p;
}

fs::path deck(const std::string& name, const std::string& text) {
  const fs::path p = dir() / name;
  std::ofstream(p) << text;
  return p;
}

// A top-level number of run.json (indented 4: the deck's echo has keys of the same names).
double top_level_number(const std::string& json, const std::string& key) {
  const std::string tag = "\n    \"" + key + "\" : ";
  const auto at = json.find(tag);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + tag.size(), nullptr);
}

// A small DPDE Cu crystal with a rigid grip and a short Berendsen start.
const std::string kGoodDpdDeck = R"(
[case]
id = "dpd_cli"
[potential]
style = "morse"
d0 = 2.7432
alpha = 0.6794
r0 = 5.732
cutoff = 12.0
[[block]]
lattice = "fcc"
constant = 7.23
cells = [4, 4, 4]
mass = 508.368
[[rigid]]
name = "grip"
x = [0.0, 3.0]
velocity = [-0.5, 0.0, 0.0]
[box]
boundary = ["f", "p", "p"]
[dpd]
ensemble = "dpde"
gamma = 0.2
temperature = 298.0
heat_capacity_kB = 21.0
seed = 5
[equilibrate]
tau = 0.5
steps = 40
[run]
dt = 0.005
steps = 60
thermo = 20
dump_every = 20
)";

TEST(DpdCli, RunWritesRecordThermoAndDump) {
  const fs::path d = deck("good.toml", kGoodDpdDeck);
  const fs::path out = dir() / "out1";
  const Result r = run_cli("dpd " + d.string() + " --out " + out.string() + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = slurp(out / "run.json");
  EXPECT_EQ(top_level_number(json, "particles"), 256);
  EXPECT_EQ(top_level_number(json, "steps"), 60);
  EXPECT_EQ(top_level_number(json, "equilibrate_steps"), 40);
  EXPECT_GT(top_level_number(json, "particle_steps_per_second"), 0);
  EXPECT_NE(json.find("\"ensemble\" : \"dpde\""), std::string::npos);
  EXPECT_NE(json.find("\"conservation\""), std::string::npos);
  const std::string thermo = slurp(out / "thermo.csv");
  EXPECT_NE(thermo.find("grip_fx_eV_per_A"), std::string::npos);
  long rows = 0, run_rows = 0;
  std::istringstream ss(thermo);
  std::string line;
  std::getline(ss, line);
  while (std::getline(ss, line)) ++rows, run_rows += line.rfind("run,", 0) == 0;
  EXPECT_EQ(rows, 3 + 4);  // equilibrate: steps 0, 20, 40; run: 40, 60, 80, 100
  EXPECT_EQ(run_rows, 4);
  const std::string dump = slurp(out / "dump.lammpstrj");
  EXPECT_NE(dump.find("ITEM: BOX BOUNDS ss pp pp"), std::string::npos);
  EXPECT_NE(dump.find("ITEM: ATOMS id type mass x y z vx vy vz u"), std::string::npos);
  std::size_t frames = 0;
  for (std::size_t at = dump.find("ITEM: TIMESTEP"); at != std::string::npos; at = dump.find("ITEM: TIMESTEP", at + 1))
    ++frames;
  EXPECT_EQ(frames, 4u);
}

TEST(DpdCli, TwoThreadsWriteTheSameThermoTable) {
  const fs::path d = deck("threads.toml", kGoodDpdDeck);
  ASSERT_EQ(run_cli("dpd " + d.string() + " --out " + (dir() / "t1").string() + " --quiet --threads 1").status, 0);
  ASSERT_EQ(run_cli("dpd " + d.string() + " --out " + (dir() / "t2").string() + " --quiet --threads 2").status, 0);
  EXPECT_EQ(slurp(dir() / "t1" / "thermo.csv"), slurp(dir() / "t2" / "thermo.csv"));
  EXPECT_EQ(slurp(dir() / "t1" / "dump.lammpstrj"), slurp(dir() / "t2" / "dump.lammpstrj"));
}

// Mean x (Angstrom), frame by frame, of the dump's particles with x < 3 in the first frame
// (the grip of kGood).
std::vector<double> grip_mean_x(const std::string& dump) {
  std::vector<std::map<long, double>> frames;
  std::istringstream ss(dump);
  bool atoms = false;
  for (std::string line; std::getline(ss, line);) {
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = line == "ITEM: ATOMS id type mass x y z vx vy vz u";
      if (atoms) frames.emplace_back();
      continue;
    }
    if (!atoms) continue;
    std::istringstream ls(line);
    long id, type;
    double mass, x;
    ls >> id >> type >> mass >> x;
    frames.back()[id] = x;
  }
  std::vector<double> out;
  for (const auto& f : frames) {
    double sum = 0;
    long n = 0;
    for (const auto& [id, x0] : frames.front())
      if (x0 < 3.0) sum += f.at(id), ++n;
    out.push_back(sum / static_cast<double>(n));
  }
  return out;
}

TEST(DpdCli, StillTwinStartsTheRigidGroupsAtRest) {
  const fs::path d = deck("still.toml", kGoodDpdDeck);
  ASSERT_EQ(run_cli("dpd " + d.string() + " --out " + (dir() / "driven").string() + " --quiet").status, 0);
  const Result r = run_cli("dpd " + d.string() + " --out " + (dir() / "still").string() + " --quiet --still");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(slurp(dir() / "still" / "run.json").find("\"still\" : true"), std::string::npos);
  EXPECT_NE(slurp(dir() / "driven" / "run.json").find("\"still\" : false"), std::string::npos);
  // The run's first row (after the same equilibration) has the same potential energy (its
  // kinetic columns count the grip's velocity); the grip then moves at -0.5 Angstrom/ps in
  // the driven run (60 steps of 0.005 ps) and not at all in the twin.
  auto first_run_row = [](const std::string& thermo) {  // phase, step, time, potential energy
    const auto at = thermo.find("\nrun,");
    std::string row = thermo.substr(at + 1, thermo.find('\n', at + 1) - at - 1);
    std::size_t cut = 0;
    for (int k = 0; k < 4; ++k) cut = row.find(',', cut + 1);
    return row.substr(0, cut);
  };
  EXPECT_EQ(first_run_row(slurp(dir() / "still" / "thermo.csv")), first_run_row(slurp(dir() / "driven" / "thermo.csv")));
  const auto still = grip_mean_x(slurp(dir() / "still" / "dump.lammpstrj"));
  const auto driven = grip_mean_x(slurp(dir() / "driven" / "dump.lammpstrj"));
  ASSERT_EQ(still.size(), 4u);
  ASSERT_EQ(driven.size(), 4u);
  EXPECT_EQ(still.back(), still.front());
  EXPECT_NEAR(driven.back() - driven.front(), -0.5 * 60 * 0.005, 1e-9);
}

TEST(DpdCli, CheckValidatesWithoutRunning) {
  const fs::path d = deck("check.toml", kGoodDpdDeck);
  const Result r = run_cli("dpd " + d.string() + " --check --out " + (dir() / "never").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("ok"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir() / "never"));
}

struct BadCase {
  const char* from;
  const char* to;
  const char* expect;  // in the message
};

TEST(DpdCli, BadDecksNameKeyValueAndReason) {
  const BadCase cases[] = {
      {"gamma = 0.2", "gamma = -0.2", "'dpd.gamma' = -0.2: must not be negative"},
      {"gamma = 0.2", "gama = 0.2", "gama"},
      {"style = \"morse\"", "style = \"lj\"", "potential.style"},
      {"cutoff = 12.0", "cutoff = 5.0", "'potential.cutoff' = 5: must exceed r0"},
      {"ensemble = \"dpde\"", "ensemble = \"dpde\"\nintegrator = \"velocity_verlet\"", "dpd.integrator"},
      {"heat_capacity_kB = 21.0", "heat_capacity_kB = 0.0", "'dpd.heat_capacity_kB' = 0: must be positive"},
      {"boundary = [\"f\", \"p\", \"p\"]", "boundary = [\"f\", \"q\", \"p\"]", "box.boundary"},
      {"cells = [4, 4, 4]", "cells = [4, 4]", "block[0].cells"},
      {"x = [0.0, 3.0]", "x = [3.0, 0.0]", "rigid[0].x"},
      {"dump_every = 20", "dump_every = 7", "'run.dump_every' = 7: must be 0 (no dump) or a multiple of thermo"},
      {"dt = 0.005", "dt = -0.005", "'run.dt' = -0.005: must be positive"},
      // Issue 31: a skin of 1000 A ran out of memory building the lists.
      {"dt = 0.005", "dt = 0.005\nskin = 1000.0", "'run.skin' = 1000: must lie in [0, "},
      // Issue 45: a cutoff past half a periodic box met particles through two images and
      // their own, and heated the fluid to 1e29 K.
      {"cells = [4, 4, 4]", "cells = [4, 3, 4]",
       "box: the pair cutoff 12 A exceeds half the periodic length along y (21.69 A)"},
      // 4e6 particles 0.21 A apart: 1.4e6 neighbours each, 87 TB of pairs (the estimate
      // per particle alone said 6 GB and let the run find out).
      {"constant = 7.23\ncells = [4, 4, 4]", "constant = 0.3\ncells = [100, 100, 100]",
       "4e+06 particles (2.73e+12 pairs within cutoff + skin) need about"},
  };
  for (const BadCase& c : cases) {
    std::string text = kGoodDpdDeck;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    text.replace(at, std::string(c.from).size(), c.to);
    const fs::path d = deck("bad.toml", text);
    const fs::path out = dir() / "bad_out";
    const Result r = run_cli("dpd " + d.string() + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << c.to << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << "expected '" << c.expect << "' in:\n" << r.output;
    EXPECT_FALSE(fs::exists(out)) << c.to;
  }
}

// A figure of a thermo row that is not finite stops the run (exit 3) naming it, its step
// and time, with the row written and run.json saying "stopped" (issue 45: a run at 1e29 K
// stopped with no run.json).
TEST(DpdCli, NonFiniteFigureStopsWithRunJson) {
  std::string text = kGoodDpdDeck;
  text.replace(text.find("mass = 508.368"), 14, "mass = 508.368\nvelocity = [1e300, 0.0, 0.0]");
  const fs::path d = deck("inf.toml", text);
  const fs::path out = dir() / "inf_out";
  fs::remove_all(out);
  const Result r = run_cli("dpd " + d.string() + " --out " + out.string() + " --quiet");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_NE(r.output.find("DPD step 0 (t = 0 ps): the kinetic energy (eV) is inf"), std::string::npos) << r.output;
  const std::string json = slurp(out / "run.json");
  EXPECT_NE(json.find("\"status\" : \"stopped\""), std::string::npos) << json;
  EXPECT_NE(json.find("the kinetic energy (eV) is inf"), std::string::npos) << json;
  EXPECT_TRUE(fs::exists(out / "thermo.csv"));
}

TEST(DpdCli, ExampleDecksValidate) {
  for (const char* name : {"D_dpd_equilibrium.toml", "D_dpde_cu_nve.toml"}) {
    const Result r = run_cli(std::string("dpd ") + MPMX_SOURCE_DIR + "/examples/" + name + " --check");
    EXPECT_EQ(r.status, 0) << name << "\n" << r.output;
  }
}

}  // namespace

namespace {

TEST(DpdCli, GridAndAnalysisKeysAreChecked) {
  // A DPD/MPM-grid deck whose cells would not fit, a track named twice, a wave speed
  // between unknown tracks, an interface of no known kind: exit 2, each key named.
  std::string text = slurp(fs::path(MPMX_SOURCE_DIR) / "examples/D3_concurrent_dpd_mpm.toml");
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  swap("file = \"cu_sc_298K_morse.toml\"", "file = \"" + std::string(MPMX_SOURCE_DIR) + "/examples/cu_sc_298K_morse.toml\"");
  swap("cell = 4.0", "cell = 0.01");
  swap("name = \"region2\"", "name = \"region1\"");
  swap("interface = \"pair_reaction\"", "interface = \"glue\"");
  const auto r = run_cli("dpd " + deck("grid_bad.toml", text).string() + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  for (const char* key : {"'grid'", "track[1].name", "analysis.wave_speed", "continuum.interface"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
}

}  // namespace

namespace {

// Issue 31: run.steps = 2^63 - 1 (or an equilibration as long) ran for ever; the work is
// estimated and refused beyond about a day, naming the key, by the run and by --check
// alike; --force takes it, and --check prints the estimate.
TEST(DpdCli, WorkBeyondADayIsRefusedUnlessForced) {
  std::string text = kGoodDpdDeck;
  const std::string from = "dt = 0.005";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const auto steps = text.find("steps = ", at);
  ASSERT_NE(steps, std::string::npos);
  // The most a run counts with its 40 equilibration steps (2^63 - 1 in all; one more is
  // refused as a count, not as work).
  text.replace(steps, text.find('\n', steps) - steps, "steps = 9223372036854775767");
  const fs::path d = deck("forever.toml", text);
  for (const std::string flags : {"", " --check"}) {
    const fs::path out = dir() / "forever_out";
    const Result r = run_cli("dpd " + d.string() + flags + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << flags << "\n" << r.output;
    EXPECT_NE(r.output.find("run.steps"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("particle-steps"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--force"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
  }
  const Result forced = run_cli("dpd " + d.string() + " --check --force");
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_NE(forced.output.find("days on one core"), std::string::npos) << forced.output;
  const Result small = run_cli("dpd " + deck("small.toml", kGoodDpdDeck).string() + " --check");
  EXPECT_EQ(small.status, 0) << small.output;
  EXPECT_NE(small.output.find("256 particles"), std::string::npos) << small.output;
}

}  // namespace
