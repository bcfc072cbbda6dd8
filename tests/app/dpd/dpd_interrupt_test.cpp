// ctest-label: slow
// Ctrl-C or SIGTERM on `mpmx dpd`: the run stops at the next record with a checkpoint,
// run.json "interrupted" and exit status 130; `--resume` (on another thread count) then
// ends with every file an uninterrupted run writes, byte for byte (run.json less its
// wall-clock figures): a DPDE crystal with a grip, stopped in its run or in its
// equilibration, and a concurrent DPD/MPM rod with its grid, continuum points, free
// flyer, tracks and profiles. A damaged checkpoint is refused (exit 2). `fit-dpd` stops
// at once: exit 130, run.json "interrupted", the stages it finished in OUT/checkpoint.bin,
// its other work (OUT/.staging) removed and nothing else in OUT changed; `--resume`
// continues from the last finished stage to the files of a fit never stopped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include "app/interrupt_util.hpp"
#include "cli_util.hpp"

namespace {

namespace fs = std::filesystem;
using mpmx::test::run_cli;
using mpmx::test::slurp;

const mpmx::test::ScratchFolder kDpdDir("mpmx_dpd_interrupt");

std::string dpd_deck(const std::string& name, const std::string& text) { return kDpdDir.file(name, text); }

// A DPDE Cu crystal with a rigid grip pulled away, after a Berendsen start.
std::string crystal(int steps) {
  return fmt::format(R"([case]
id = "dpd_interrupt"
[potential]
style = "morse"
d0 = 2.7432
alpha = 0.6794
r0 = 5.732
cutoff = 12.0
[[block]]
lattice = "fcc"
constant = 7.23
cells = [5, 4, 4]
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
steps = {}
thermo = 20
dump_every = 100
)",
                     steps);
}

// A concurrent DPD/MPM rod (D3 shrunk): continuum points on the left, a free flyer on the
// right, the grid, tracks and displacement profiles.
const std::string kConcurrent = R"([case]
id = "dpd_concurrent_interrupt"
[potential]
style = "morse"
d0 = 2.7432
alpha = 0.6794
r0 = 5.732
cutoff = 12.0
[[block]]
lattice = "fcc"
constant = 7.293
cells = [10, 3, 3]
mass = 508.368
[[block]]
lattice = "fcc"
constant = 7.293
cells = [2, 3, 3]
origin = [76.58, 0, 0]
mass = 508.368
group = "flyer"
velocity = [-5.0, 0, 0]
free = true
[box]
size = [95.0, 21.879, 21.879]
boundary = ["f", "f", "f"]
[dpd]
ensemble = "dpde"
gamma = 0.2
temperature = 298.0
heat_capacity_kB = 21.0
seed = 7
[equilibrate]
temperature = 298.0
tau = 1.0
steps = 20
[run]
dt = 0.005
steps = 160
thermo = 20
dump_every = 80
[grid]
cell = 4.0
margin = 40.0
[continuum]
x = [-100.0, 30.0]
lattice_constant = 7.293
[[track]]
name = "near"
x = [55.0, 62.0]
[[track]]
name = "far"
x = [10.0, 20.0]
[analysis]
every = 5
onset = 0.3
onset_direction = -1
wave_speed = ["near", "far"]
[profile]
bins = 6
every = 40
)";

std::string whole_run(const std::string& d, const std::string& name) {
  const fs::path whole = kDpdDir / (name + "_whole");
  const auto w = run_cli(fmt::format("dpd '{}' --quiet --no-plot --threads 2 --out '{}'", d, whole.string()));
  EXPECT_EQ(w.status, 0) << w.output;
  return whole.string();
}

void resume_and_compare(const std::string& d, const fs::path& whole, const fs::path& cut) {
  const auto r = run_cli(fmt::format("dpd '{}' --quiet --no-plot --threads 1 --out '{}' --resume", d, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

TEST(DpdInterrupt, CtrlCInTheRunResumesToTheSameFiles) {
  const std::string d = dpd_deck("crystal.toml", crystal(3000));
  const fs::path whole = whole_run(d, "crystal"), cut = kDpdDir / "crystal_cut";
  const std::string log = (kDpdDir / "crystal.log").string();
  // Past the equilibration's 3 rows and a few of the run's.
  const int status = mpmx::test::signal_when(
      fmt::format("'{}' dpd '{}' --quiet --no-plot --threads 2 --out '{}'", MPMX_BINARY, d, cut.string()),
      (cut / ".staging" / "thermo.csv").string(), 12, "INT", log);
  ASSERT_EQ(status, 130) << slurp(log);
  EXPECT_NE(slurp(log).find(fmt::format("written to {}/checkpoint.bin; continue with: mpmx dpd {} --out {} --resume",
                                        cut.string(), d, cut.string())),
            std::string::npos)
      << slurp(log);
  ASSERT_TRUE(fs::exists(cut / "checkpoint.bin"));
  EXPECT_NE(slurp(cut / "run.json").find("\"status\" : \"interrupted\""), std::string::npos);
  resume_and_compare(d, whole, cut);
}

TEST(DpdInterrupt, StoppedInTheEquilibrationResumesToTheSameFiles) {
  const std::string d = dpd_deck("equilibrating.toml", crystal(100));
  const fs::path whole = whole_run(d, "equilibrating"), cut = kDpdDir / "equilibrating_cut";
  const auto stop =
      run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --stop-after 20", d, cut.string()));
  ASSERT_EQ(stop.status, 130) << stop.output;
  EXPECT_NE(stop.output.find("step 20 of 140 written to"), std::string::npos) << stop.output;
  resume_and_compare(d, whole, cut);
}

TEST(DpdInterrupt, TheConcurrentRodResumesToTheSameFiles) {
  const std::string d = dpd_deck("concurrent.toml", kConcurrent);
  const fs::path whole = whole_run(d, "concurrent"), cut = kDpdDir / "concurrent_cut";
  const auto stop =
      run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --stop-after 85", d, cut.string()));
  ASSERT_EQ(stop.status, 130) << stop.output;
  EXPECT_NE(stop.output.find("step 85 of 180 written to"), std::string::npos) << stop.output;
  for (const char* f : {"tracks.csv", "profile.csv"}) EXPECT_TRUE(fs::exists(whole / f)) << f;
  resume_and_compare(d, whole, cut);
}

// Stopped two and three times (in the equilibration, between records, on one): the
// same files; the concurrent rod twice.
TEST(DpdInterrupt, StoppedAgainAndAgainResumesToTheSameFiles) {
  const std::string d = dpd_deck("again.toml", crystal(100)), rod = dpd_deck("again_rod.toml", kConcurrent);
  const fs::path whole = whole_run(d, "again"), rod_whole = whole_run(rod, "again_rod");
  for (const auto& [deck, w, stops] : std::vector<std::tuple<std::string, fs::path, std::vector<int>>>{
           {d, whole, {20, 60}}, {d, whole, {10, 45, 100}}, {rod, rod_whole, {30, 105}}}) {
    const fs::path cut = kDpdDir / fmt::format("again_{}_{}", deck == rod ? "rod" : "crystal", stops.size());
    std::string resume;
    for (int s : stops) {
      const auto r = run_cli(
          fmt::format("dpd '{}' --quiet --no-plot --out '{}' --stop-after {}{}", deck, cut.string(), s, resume));
      ASSERT_EQ(r.status, 130) << r.output;
      resume = " --resume";
    }
    resume_and_compare(deck, w, cut);
  }
}

TEST(DpdInterrupt, ADamagedCheckpointIsRefused) {
  const std::string d = dpd_deck("damaged.toml", crystal(100));
  const fs::path cut = kDpdDir / "damaged";
  ASSERT_EQ(run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --stop-after 60", d, cut.string())).status,
            130);
  const fs::path ck = cut / "checkpoint.bin";
  const std::string good = slurp(ck);
  ASSERT_GT(good.size(), 1000u);
  std::string bad = good;
  bad[bad.size() / 3] ^= 0x01;
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << bad;
  auto r = run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("the payload is damaged"), std::string::npos) << r.output;
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << good.substr(0, good.size() - 9);
  r = run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << good;
  r = run_cli(fmt::format("dpd '{}' --quiet --no-plot --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 0) << r.output;
}

TEST(DpdInterrupt, FitDpdStopsAtOnceLeavingOutAsItWas) {
  const fs::path out = kDpdDir / "fit";
  fs::create_directories(out);
  std::ofstream(out / "earlier.csv") << "an earlier run's table\n";
  const std::string log = (kDpdDir / "fit.log").string();
  const int status = mpmx::test::signal_when(
      fmt::format("'{}' fit-dpd '{}/examples/D0_md_to_dpd_fit.toml' --threads 1 --out '{}'", MPMX_BINARY,
                  MPMX_SOURCE_DIR, out.string()),
      (out / ".staging").string(), 0, "INT", log);
  ASSERT_EQ(status, 130) << slurp(log);
  EXPECT_NE(slurp(log).find("fit-dpd stopped"), std::string::npos) << slurp(log);
  EXPECT_NE(slurp(out / "run.json").find("\"status\" : \"interrupted\""), std::string::npos);
  EXPECT_EQ(slurp(out / "earlier.csv"), "an earlier run's table\n");
  EXPECT_FALSE(fs::exists(out / ".staging"));  // half a fit is no result to leave in the user's folder
  EXPECT_FALSE(fs::exists(out / "isotherm.csv"));
  EXPECT_FALSE(fs::exists(out / ".mpmx-lock"));  // gone with the run that held it
}

// D0 with [elastic] made small: 3 densities of 108 atoms, 108 mesoparticles, 2 rounds.
std::string tiny_fit() {
  return dpd_deck("tiny_fit.toml", R"([case]
id = "fit_tiny"
[md.potential]
style = "sutton_chen"
epsilon = 1.2382e-2
a = 3.61
c = 39.432
n = 9
m = 6
cutoff = 9.0
mass = 63.546
[md]
lattice_constant = 3.61
cells = 3
temperature = 298.0
dt = 0.002
equilibrate_steps = 200
sample_steps = 200
seed = 1
[densities]
from = 0.95
to = 1.05
points = 3
[dpd]
atoms_per_particle = 8
cutoff = 12.0
start = { d0 = 2.7432, alpha = 0.6794, r0 = 5.732 }
cells = 3
gamma = 0.2
heat_capacity_kB = 21.0
dt = 0.005
equilibrate_steps = 100
sample_steps = 200
iterations = 2
seed = 1
[elastic]
weight = 1.0
strain = 0.01
md_sample_steps = 200
dpd_sample_steps = 200
[output]
potential_file = "tiny_morse.toml"
)");
}

// run.json less its wall-clock figures.
std::string physics_of(const fs::path& run_json) {
  std::string kept, line;
  std::istringstream in(slurp(run_json));
  while (std::getline(in, line))
    if (line.find("wall_seconds") == std::string::npos && line.find("\"threads\"") == std::string::npos)
      kept += line + "\n";
  return kept;
}

// Stopped after each of its stages in turn (the MD isotherm, the MD constants, round 0,
// round 1), then resumed on another thread count: the files of a fit never stopped.
TEST(DpdInterrupt, FitDpdResumesFromItsLastStageToTheSameFiles) {
  const std::string d = tiny_fit();
  const fs::path whole = kDpdDir / "fit_whole";
  auto r = run_cli(fmt::format("fit-dpd '{}' --threads 2 --out '{}'", d, whole.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  for (int stage : {1, 2, 3, 4}) {
    const fs::path cut = kDpdDir / fmt::format("fit_cut_{}", stage);
    r = run_cli(fmt::format("fit-dpd '{}' --threads 2 --out '{}' --stop-after {}", d, cut.string(), stage));
    ASSERT_EQ(r.status, 130) << r.output;
    EXPECT_NE(r.output.find("--resume"), std::string::npos) << r.output;
    ASSERT_TRUE(fs::exists(cut / "checkpoint.bin")) << stage;
    EXPECT_NE(slurp(cut / "run.json").find("\"status\" : \"interrupted\""), std::string::npos);
    r = run_cli(fmt::format("fit-dpd '{}' --threads 1 --out '{}' --resume", d, cut.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    for (const char* f : {"isotherm.csv", "tiny_morse.toml"}) EXPECT_EQ(slurp(whole / f), slurp(cut / f)) << stage << f;
    EXPECT_EQ(physics_of(whole / "run.json"), physics_of(cut / "run.json")) << stage;
    EXPECT_FALSE(fs::exists(cut / "checkpoint.bin"));
    EXPECT_FALSE(fs::exists(cut / ".staging"));
  }
  // Stopped after the MD isotherm, then after round 0, then resumed: the same files.
  {
    const fs::path cut = kDpdDir / "fit_cut_again";
    for (const char* step : {"--stop-after 1", "--resume --stop-after 3", "--resume"}) {
      r = run_cli(fmt::format("fit-dpd '{}' --threads 2 --out '{}' {}", d, cut.string(), step));
      ASSERT_EQ(r.status, std::string(step) == "--resume" ? 0 : 130) << step << r.output;
    }
    for (const char* f : {"isotherm.csv", "tiny_morse.toml"}) EXPECT_EQ(slurp(whole / f), slurp(cut / f)) << f;
    EXPECT_EQ(physics_of(whole / "run.json"), physics_of(cut / "run.json"));
    EXPECT_FALSE(fs::exists(cut / "checkpoint.bin"));
  }
  // Another deck's checkpoint, and none at all, are refused with exit 2.
  const fs::path cut = kDpdDir / "fit_cut_other";
  r = run_cli(fmt::format("fit-dpd '{}' --threads 2 --out '{}' --stop-after 1", d, cut.string()));
  ASSERT_EQ(r.status, 130) << r.output;
  std::string other = slurp(d);
  other.replace(other.find("seed = 1"), 8, "seed = 2");
  const std::string d2 = dpd_deck("tiny_fit_other.toml", other);
  r = run_cli(fmt::format("fit-dpd '{}' --out '{}' --resume", d2, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("another deck"), std::string::npos) << r.output;
  r = run_cli(fmt::format("fit-dpd '{}' --out '{}' --resume", d, (kDpdDir / "fit_nothing").string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("no checkpoint to resume from"), std::string::npos) << r.output;
}

}  // namespace
