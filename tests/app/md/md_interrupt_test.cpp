// ctest-label: slow
// Ctrl-C or SIGTERM on `mpmx md`: the run stops at the next record with a checkpoint,
// run.json "interrupted" and exit status 130; `--resume` (on another thread count) then
// ends with every file an uninterrupted run writes, byte for byte (run.json less its
// wall-clock figures): the jet with its bins, images and dumps, a thermalised box with
// its thermo rows and dump under every ensemble, the bar. A damaged checkpoint is
// refused (exit 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/interrupt_util.hpp"
#include "cli_util.hpp"

namespace {

namespace fs = std::filesystem;
using mpmx::test::run_cli;
using mpmx::test::slurp;

const mpmx::test::ScratchFolder kMdDir("mpmx_md_interrupt");

std::string md_deck(const std::string& name, const std::string& text) { return kMdDir.file(name, text); }

const std::string kLj = R"([potential]
style = "lj"
epsilon = 0.4
sigma = 2.3
cutoff = 5.0
mass = 63.5
)";

// A thermalised Lennard-Jones box: relaxed, then run with thermo rows and a dump.
const std::string kBox = kLj + R"([lattice]
constant = 3.615
cells = [6, 6, 6]
[thermal]
temperature = 300.0
seed = 3
relax_steps = 40
[run]
dt = 0.002
steps = 6000
thermo = 40
dump_every = 400
)";

// A bar of the same crystal with its left half compressed.
const std::string kBar = kLj + R"([lattice]
constant = 3.615
cells = [1, 1, 1]
[thermal]
temperature = 50.0
seed = 2
[run]
dt = 0.002
steps = 600
[bar]
cells_x = 24
cells_yz = 3
strain_left = -0.01
bins = 6
output_every = 50
)";

// The run whole; then on `threads` threads signalled once `table` (in its staging folder)
// has `lines` lines and resumed on `resume_threads`: the same files.
void interrupt_and_resume(const std::string& deck_path, const std::string& name, const std::string& table, int lines,
                          const std::string& signal, int threads = 2, int resume_threads = 1) {
  const fs::path whole = kMdDir / (name + "_whole"), cut = kMdDir / (name + "_cut");
  const std::string run = fmt::format("md '{}' --quiet --threads {}", deck_path, threads);
  const auto w = run_cli(fmt::format("{} --out '{}'", run, whole.string()));
  ASSERT_EQ(w.status, 0) << w.output;
  const std::string log = (kMdDir / (name + ".log")).string();
  const int status = mpmx::test::signal_when(fmt::format("'{}' {} --out '{}'", MPMX_BINARY, run, cut.string()),
                                             (cut / ".staging" / table).string(), lines, signal, log);
  ASSERT_EQ(status, 130) << slurp(log);
  const std::string message = slurp(log);
  EXPECT_NE(message.find(fmt::format("written to {}/checkpoint.bin; continue with: mpmx md {} --out {} --resume",
                                     cut.string(), deck_path, cut.string())),
            std::string::npos)
      << message;
  ASSERT_TRUE(fs::exists(cut / "checkpoint.bin"));
  EXPECT_FALSE(fs::exists(cut / ".staging"));
  const std::string json = slurp(cut / "run.json");
  EXPECT_NE(json.find("\"status\" : \"interrupted\""), std::string::npos) << json;
  EXPECT_NE(json.find("checkpoint.bin"), std::string::npos);
  const auto r = run_cli(
      fmt::format("md '{}' --quiet --threads {} --out '{}' --resume", deck_path, resume_threads, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

TEST(MdInterrupt, CtrlCOnTheJetResumesToTheSameFiles) {
  interrupt_and_resume(std::string(MPMX_SOURCE_DIR) + "/examples/J1_direct_md_tiny.toml", "jet", "jet_front.csv", 4,
                       "INT");
}

TEST(MdInterrupt, SigtermOnABoxResumesToTheSameFiles) {
  interrupt_and_resume(md_deck("box.toml", kBox), "box", "thermo.csv", 8, "TERM", 1, 2);
}

TEST(MdInterrupt, CtrlCOnABoxResumesToTheSameFiles) {
  interrupt_and_resume(md_deck("box_int.toml", kBox), "box_int", "thermo.csv", 8, "INT");
}

// The barostat alone takes its kT from the box it starts with, the Hugoniostat its
// reference state: a resume takes neither again (SIGTERM, as a batch system sends it).
TEST(MdInterrupt, SigtermOnAnNphBoxResumesToTheSameFiles) {
  interrupt_and_resume(md_deck("box_nph.toml", kBox + "ensemble = \"nph\"\n"), "box_nph", "thermo.csv", 8, "TERM", 1,
                       2);
}

TEST(MdInterrupt, SigtermOnAHugoniostatResumesToTheSameFiles) {
  interrupt_and_resume(md_deck("box_nphug.toml", kBox + "ensemble = \"nphug\"\npressure_gpa = 2.0\n"), "box_nphug",
                       "thermo.csv", 8, "TERM", 2, 1);
}

// A box under each ensemble, relaxed for a number of steps thermo does not divide, with
// thermo rows, a dump and (nphug) the Hugoniot's mean over the run's second half.
std::string ensemble_box(const std::string& ensemble) {
  std::string t = kLj + R"([lattice]
constant = 3.615
cells = [4, 4, 4]
[thermal]
temperature = 300.0
seed = 5
relax_steps = 30
[run]
dt = 0.002
steps = 400
thermo = 20
dump_every = 100
dump_fields = ["pe"]
)";
  t += fmt::format("ensemble = \"{}\"\n", ensemble);
  if (ensemble == "npt") t += "barostat = \"aniso\"\npressure_gpa = [0.5, 0.0, 0.0]\n";
  if (ensemble == "nphug") t += "pressure_gpa = 2.0\nshock_axis = \"y\"\n";
  return t;
}

// Every ensemble stopped once, twice, and at its first and last records before the end
// (the stop comes at the first thermo row at or past the step: after the 30 steps'
// relaxation the rows fall at steps 40, 60, ..., 420 and 430), resumed each time: every
// file the uninterrupted run's.
TEST(MdInterrupt, EveryEnsembleStoppedAnywhereResumesToTheSameFiles) {
  for (const std::string ensemble : {"nve", "nvt", "npt", "nph", "nphug"}) {
    SCOPED_TRACE(ensemble);
    const std::string d = md_deck(ensemble + ".toml", ensemble_box(ensemble));
    const fs::path whole = kMdDir / (ensemble + "_whole");
    const auto w = run_cli(fmt::format("md '{}' --quiet --out '{}'", d, whole.string()));
    ASSERT_EQ(w.status, 0) << w.output;
    if (ensemble == "nphug") {
      EXPECT_NE(slurp(whole / "run.json").find("\"rows_averaged\" : 11"), std::string::npos);
    }
    for (const auto& stops : std::vector<std::vector<int>>{{100}, {45, 230}, {20, 420}}) {
      const fs::path cut = kMdDir / fmt::format("{}_{}_{}", ensemble, stops.front(), stops.size());
      std::string resume;
      for (int s : stops) {
        const auto r = run_cli(fmt::format("md '{}' --quiet --out '{}' --stop-after {}{}", d, cut.string(), s, resume));
        ASSERT_EQ(r.status, 130) << r.output;
        const int row = std::max(40, (s + 19) / 20 * 20);
        EXPECT_NE(r.output.find(fmt::format("step {} of 430 written to", row)), std::string::npos)
            << r.output;
        resume = " --resume";
      }
      const auto r = run_cli(fmt::format("md '{}' --quiet --out '{}' --resume", d, cut.string()));
      ASSERT_EQ(r.status, 0) << r.output;
      mpmx::test::expect_same_folders(whole, cut);
    }
  }
}

TEST(MdInterrupt, TheBarStoppedAtARecordResumesToTheSameFiles) {
  const std::string d = md_deck("bar.toml", kBar);
  const fs::path whole = kMdDir / "bar_whole", cut = kMdDir / "bar_cut";
  ASSERT_EQ(run_cli(fmt::format("md '{}' --quiet --out '{}'", d, whole.string())).status, 0);
  const auto stop = run_cli(fmt::format("md '{}' --quiet --out '{}' --stop-after 200", d, cut.string()));
  ASSERT_EQ(stop.status, 130) << stop.output;
  EXPECT_NE(stop.output.find("step 200 of 600 written to"), std::string::npos) << stop.output;
  const auto r = run_cli(fmt::format("md '{}' --quiet --threads 2 --out '{}' --resume", d, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

// Stopped two and three times, between records and on one (the bar records every 50
// steps, the stop comes at the first record at or past the step): the same files.
TEST(MdInterrupt, TheBarStoppedAgainAndAgainResumesToTheSameFiles) {
  const std::string d = md_deck("bar_again.toml", kBar);
  const fs::path whole = kMdDir / "bar_again_whole";
  ASSERT_EQ(run_cli(fmt::format("md '{}' --quiet --out '{}'", d, whole.string())).status, 0);
  for (const auto& stops : std::vector<std::vector<int>>{{100, 150}, {20, 130, 550}}) {
    const fs::path cut = kMdDir / fmt::format("bar_again_{}", stops.size());
    std::string resume;
    for (int s : stops) {
      const auto r = run_cli(fmt::format("md '{}' --quiet --out '{}' --stop-after {}{}", d, cut.string(), s, resume));
      ASSERT_EQ(r.status, 130) << r.output;
      resume = " --resume";
    }
    const auto r = run_cli(fmt::format("md '{}' --quiet --threads 2 --out '{}' --resume", d, cut.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    mpmx::test::expect_same_folders(whole, cut);
  }
}

TEST(MdInterrupt, ADamagedCheckpointIsRefused) {
  const std::string d = md_deck("damaged.toml", kBar);
  const fs::path cut = kMdDir / "damaged";
  ASSERT_EQ(run_cli(fmt::format("md '{}' --quiet --out '{}' --stop-after 100", d, cut.string())).status, 130);
  const fs::path ck = cut / "checkpoint.bin";
  std::string bytes = slurp(ck);
  ASSERT_GT(bytes.size(), 1000u);
  const std::string good = bytes;
  bytes[bytes.size() / 2] ^= 0x20;  // a flipped bit in the payload
  std::ofstream(ck, std::ios::binary) << bytes;
  auto r = run_cli(fmt::format("md '{}' --quiet --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("the payload is damaged"), std::string::npos) << r.output;
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << good.substr(0, 40);  // cut inside the header
  r = run_cli(fmt::format("md '{}' --quiet --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  // Another deck's checkpoint.
  std::ofstream(ck, std::ios::binary | std::ios::trunc) << good;
  std::string changed = kBar;
  changed.replace(changed.find("seed = 2"), 8, "seed = 4");
  const std::string other = md_deck("other.toml", changed);
  r = run_cli(fmt::format("md '{}' --quiet --out '{}' --resume", other, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("another deck"), std::string::npos) << r.output;
  // The file is left as it was for a good resume.
  r = run_cli(fmt::format("md '{}' --quiet --out '{}' --resume", d, cut.string()));
  EXPECT_EQ(r.status, 0) << r.output;
}

}  // namespace
