// One output folder, one run; every interruption resumable; the machine's failures said
// as such; inputs pinned by the checkpoint. `mpmx run` on a 1-D standing wave (a fifth of
// a second a run) and a tiny MD box: a second run into a locked folder is refused before
// it writes; another deck's folder is refused unless --overwrite, which removes that
// run's files and no one else's; a run stopped at many steps, once, twice and three
// times, ends with the files of a run never stopped; two SIGTERMs (GNU timeout's) and a
// kill -9 leave a checkpoint to resume from and no temporary file; a write refused by the
// system (a file size limit standing in for a full disk) exits 1 naming the file and
// leaves the earlier run and the last checkpoint as they were; a potential file changed
// under a checkpoint, or a checkpoint of an older format, is refused by name.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/interrupt_util.hpp"
#include "app/mpm/disk_on_wall.hpp"
#include "cli_util.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/io/folder_lock.hpp"

namespace output_folder_test {

namespace fs = std::filesystem;
using mpmx::test::run_cli;
using mpmx::test::slurp;

const mpmx::test::ScratchFolder kDir("mpmx_output_folder");

const std::string kWave = std::string(MPMX_SOURCE_DIR) + "/examples/A1_standing_wave_static.toml";
const std::string kMoving = std::string(MPMX_SOURCE_DIR) + "/examples/A1_standing_wave_moving.toml";
const std::string kRun = "--quiet --no-plot";

// The standing wave on 3,000,000 steps of 1e-7 (about 3 s): long enough to signal.
std::string long_wave() {
  std::string t = slurp(kWave);
  for (auto [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"dt = 1e-5", "dt = 1e-7"}, {"end = 2.1", "end = 0.3"}, {"times = [0.3, 1.2, 2.1]", "times = [0.1, 0.3]"}})
    while (t.find(from) != std::string::npos) t.replace(t.find(from), from.size(), to);
  return kDir.file("long_wave.toml", t);
}

using mpmx::test::snapshot;

// A shell command line's exit status.
int shell(const std::string& line) {
  const int status = std::system(("bash -c '" + line + "'").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The whole run of `deck` into `name`, once per test program.
fs::path whole_of(const std::string& deck, const std::string& name) {
  const fs::path whole = kDir / name;
  if (!fs::exists(whole / "run.json")) {
    const auto r = run_cli(fmt::format("run '{}' {} --out '{}'", deck, kRun, whole.string()));
    EXPECT_EQ(r.status, 0) << r.output;
  }
  return whole;
}

TEST(OutputFolder, ASecondRunIntoALockedFolderIsRefusedBeforeItWrites) {
  const fs::path out = kDir / "locked";
  fs::create_directories(out / ".staging");
  std::ofstream(out / ".staging" / "energy.csv") << "the first run's";
  {
    const mpmx::io::FolderLock first(out.string());
    const auto r = run_cli(fmt::format("run '{}' {} --out '{}'", kWave, kRun, out.string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("another mpmx run is writing into this folder"), std::string::npos) << r.output;
    EXPECT_EQ(slurp(out / ".staging" / "energy.csv"), "the first run's");  // its staging untouched
    EXPECT_FALSE(fs::exists(out / "run.json"));
  }
  EXPECT_FALSE(fs::exists(out / ".mpmx-lock"));  // the lock's file goes with its holder
  const auto r = run_cli(fmt::format("run '{}' {} --out '{}'", kWave, kRun, out.string()));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / ".staging"));
  EXPECT_FALSE(fs::exists(out / ".mpmx-lock"));
}

TEST(OutputFolder, AnotherRunsFolderIsRefusedUnlessOverwriteThenItsFilesAllGo) {
  const fs::path out = kDir / "other";
  const std::string box = kDir.file("box.toml", R"([potential]
style = "lj"
epsilon = 0.4
sigma = 2.3
cutoff = 5.0
mass = 63.5
[lattice]
constant = 3.615
cells = [3, 3, 3]
[run]
dt = 0.002
steps = 40
thermo = 10
dump_every = 20
)");
  auto r = run_cli(fmt::format("md '{}' --quiet --threads 1 --out '{}'", box, out.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(fs::exists(out / "thermo.csv"));
  // The user's own files beside the run's, one inside a folder of the same name as a run's.
  fs::create_directories(out / "vtk");
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(out / "vtk" / "mine.txt") << "mine too";
  const auto before = snapshot(out);
  r = run_cli(fmt::format("run '{}' {} --out '{}'", kWave, kRun, out.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("holds the results of another run"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  EXPECT_EQ(snapshot(out), before);
  r = run_cli(fmt::format("run '{}' {} --out '{}' --overwrite", kWave, kRun, out.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "thermo.csv"));
  EXPECT_FALSE(fs::exists(out / "dump.lammpstrj"));
  EXPECT_EQ(slurp(out / "notes.txt"), "mine");
  EXPECT_EQ(slurp(out / "vtk" / "mine.txt"), "mine too");
  const fs::path whole = whole_of(kWave, "wave_whole");
  for (const char* f : {"nodes.csv", "particles.csv", "energy.csv"}) EXPECT_EQ(slurp(out / f), slurp(whole / f)) << f;
  // A rerun of the same deck and command into its own folder is let in, as always.
  r = run_cli(fmt::format("run '{}' {} --out '{}'", kWave, kRun, out.string()));
  EXPECT_EQ(r.status, 0) << r.output;
  // Another deck of the same command is another run.
  r = run_cli(fmt::format("run '{}' {} --out '{}'", kMoving, kRun, out.string()));
  EXPECT_EQ(r.status, 2) << r.output;
}

// The 2-D disk against a wall (recorded every 100 steps into vtk/), run to `end`.
std::string disk(const std::string& end) {
  std::string t = mpmx::test::kDiskOnWall;
  t.replace(t.find("end = 5.0"), 9, "end = " + end);
  return kDir.file("disk.toml", t);
}

// `--out .` in the user's folder: a rerun of the deck, shorter, replaces the run's
// vtk/ frames (the earlier run's later frames go) and keeps the user's file in vtk/.
TEST(OutputFolder, ARerunReplacesOnlyTheFilesMpmxWrote) {
  const fs::path here = kDir / "dot";
  fs::create_directories(here / "vtk");
  std::ofstream(here / "vtk" / "mine.txt") << "mine";
  std::ofstream(here / "notes.txt") << "mine";
  const std::string run =
      fmt::format("cd \"{}\" && \"{}\" run \"{}\" {} --out .", here.string(), MPMX_BINARY, disk("5.0"), kRun);
  ASSERT_EQ(shell(run), 0);
  std::size_t frames = 0;
  for (const auto& e : fs::directory_iterator(here / "vtk")) frames += e.path().extension() == ".vtu";
  ASSERT_GE(frames, 5u);
  disk("2.0");
  ASSERT_EQ(shell(run), 0);
  std::size_t after = 0;
  for (const auto& e : fs::directory_iterator(here / "vtk")) after += e.path().extension() == ".vtu";
  EXPECT_LT(after, frames);
  EXPECT_GE(after, 2u);
  EXPECT_EQ(slurp(here / "vtk" / "mine.txt"), "mine");
  EXPECT_EQ(slurp(here / "notes.txt"), "mine");
}

// Stopped after each step of `stops` in turn (--stop-after: a checkpoint at that step,
// exit 130), resumed each time, then resumed to the end: the whole run's files.
void stop_at(const std::vector<int>& stops) {
  const fs::path whole = whole_of(kWave, "wave_whole");
  std::string name = "stops";
  for (int s : stops) name += "_" + std::to_string(s);
  const fs::path cut = kDir / name;
  bool resume = false;
  for (int s : stops) {
    const auto r = run_cli(fmt::format("run '{}' {} --out '{}' --stop-after {}{}", kWave, kRun, cut.string(), s,
                                       resume ? " --resume" : ""));
    ASSERT_EQ(r.status, 130) << name << ": " << r.output;
    resume = true;
  }
  const auto r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", kWave, kRun, cut.string()));
  ASSERT_EQ(r.status, 0) << name << ": " << r.output;
  SCOPED_TRACE(name);
  mpmx::test::expect_same_folders(whole, cut);
}

// The records are at steps 0, 30000 (t = 0.3), 120000 and 210000: stops between two of
// them (twice before the first: that lost the t = 0 record), on one, just after one.
TEST(OutputFolder, StoppedOnceTwiceOrThriceAtAnyStepResumesToTheWholeRun) {
  for (const auto& stops : std::vector<std::vector<int>>{{1},
                                                         {1, 2},
                                                         {1000, 2000},
                                                         {1000, 2000, 3000},
                                                         {29999, 30000, 30001},
                                                         {30000, 60000},
                                                         {500, 120000, 209999}})
    stop_at(stops);
}

// The 2-D disk (records every 100 steps into vtk/ and particles.pvd) stopped between
// records twice, then on one: the whole run's files.
TEST(OutputFolder, The2DRunStoppedAgainAndAgainResumesToTheWholeRun) {
  const std::string deck = disk("2.0");
  const fs::path whole = kDir / "disk_whole", cut = kDir / "disk_cut";
  auto r = run_cli(fmt::format("run '{}' {} --out '{}'", deck, kRun, whole.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(fs::exists(whole / "vtk"));
  std::string resume;
  for (int s : {50, 60, 100}) {
    r = run_cli(fmt::format("run '{}' {} --out '{}' --stop-after {}{}", deck, kRun, cut.string(), s, resume));
    ASSERT_EQ(r.status, 130) << r.output;
    resume = " --resume";
  }
  r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", deck, kRun, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

// GNU timeout sends SIGTERM to the run and then to its process group: the second is the
// same request, so the run still ends with its checkpoint (exit 130, timeout's 124).
TEST(OutputFolder, TheTwoSigtermsOfTimeoutLeaveACheckpointThatResumes) {
  const std::string deck = long_wave();
  const fs::path whole = kDir / "long_whole", cut = kDir / "long_timeout";
  auto r = run_cli(fmt::format("run '{}' {} --out '{}'", deck, kRun, whole.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  const int status = shell(fmt::format("timeout -s TERM 1 \"{}\" run \"{}\" {} --out \"{}\" 2> \"{}.log\"", MPMX_BINARY,
                                       deck, kRun, cut.string(), cut.string()));
  ASSERT_EQ(status, 124) << slurp(cut.string() + ".log");
  EXPECT_NE(slurp(cut.string() + ".log").find("interrupted"), std::string::npos) << slurp(cut.string() + ".log");
  ASSERT_TRUE(fs::exists(cut / "checkpoint.bin"));
  r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", deck, kRun, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

// kill -9 after a periodic checkpoint (in the staging folder), a checkpoint write cut
// short beside it: --resume continues from the checkpoint and the finished folder holds
// no temporary file.
TEST(OutputFolder, AKilledRunResumesAndLeavesNoTemporaryFile) {
  const std::string deck = long_wave();
  const fs::path whole = kDir / "long_whole_kill", cut = kDir / "long_kill";
  auto r = run_cli(fmt::format("run '{}' {} --out '{}'", deck, kRun, whole.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string ck = (cut / ".staging" / "checkpoint.bin").string();
  shell(fmt::format("\"{}\" run \"{}\" {} --out \"{}\" --checkpoint-every 100000 & pid=$!; "
                    "for i in $(seq 300); do [ -e \"{}\" ] && break; sleep 0.05; done; kill -KILL $pid; wait $pid",
                    MPMX_BINARY, deck, kRun, cut.string(), ck));
  ASSERT_TRUE(fs::exists(ck));
  std::ofstream(ck + ".tmp");  // 0 bytes: a write the kill cut
  r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", deck, kRun, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  for (const auto& e : fs::recursive_directory_iterator(cut)) EXPECT_NE(e.path().extension(), ".tmp") << e.path();
  mpmx::test::expect_same_folders(whole, cut);
}

// A write the system refuses (here past a file size limit, as a full disk would):
// exit 1 naming the file and the system's reason, never "internal error"; the earlier
// finished run and the last checkpoint stay as they were.
TEST(OutputFolder, AWriteTheSystemRefusesIsSaidAndLosesNothing) {
  const fs::path whole = whole_of(kWave, "wave_whole");
  const fs::path done = kDir / "full_done";
  auto r = run_cli(fmt::format("run '{}' {} --out '{}'", kWave, kRun, done.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  const auto finished = snapshot(done);
  const std::string limited = fmt::format("ulimit -f 20; \"{}\" run \"{}\" {} --out ", MPMX_BINARY, kWave, kRun);
  // The tables: energy.csv passes 20 kB.
  EXPECT_EQ(shell(limited + fmt::format("\"{}\" 2> \"{}.log\"", done.string(), done.string())), 1);
  std::string log = slurp(done.string() + ".log");
  EXPECT_NE(log.find("the file system failed"), std::string::npos) << log;
  EXPECT_NE(log.find("energy.csv: File too large"), std::string::npos) << log;
  EXPECT_EQ(log.find("internal error"), std::string::npos) << log;
  EXPECT_EQ(snapshot(done), finished);
  // The interrupt checkpoint (10 kB, the tables at step 1000 less than 8 kB).
  EXPECT_EQ(shell(fmt::format("ulimit -f 9; \"{}\" run \"{}\" {} --out \"{}\" --stop-after 1000 2> \"{}.log\"",
                              MPMX_BINARY, kWave, kRun, done.string(), done.string())),
            1);
  log = slurp(done.string() + ".log");
  EXPECT_NE(log.find("writing " + (done / ".staging" / "checkpoint.bin").string() + ": write failed: "),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("File too large"), std::string::npos) << log;
  EXPECT_EQ(snapshot(done), finished);
  // A resumed run the disk stops keeps its checkpoint, and resumes once there is room.
  const fs::path cut = kDir / "full_resume";
  r = run_cli(fmt::format("run '{}' {} --out '{}' --stop-after 1000", kWave, kRun, cut.string()));
  ASSERT_EQ(r.status, 130) << r.output;
  const std::string checkpoint = slurp(cut / "checkpoint.bin");
  EXPECT_EQ(shell(limited + fmt::format("\"{}\" --resume 2> \"{}.log\"", cut.string(), cut.string())), 1);
  EXPECT_NE(slurp(cut.string() + ".log").find("File too large"), std::string::npos) << slurp(cut.string() + ".log");
  EXPECT_EQ(slurp(cut / "checkpoint.bin"), checkpoint);
  r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", kWave, kRun, cut.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  mpmx::test::expect_same_folders(whole, cut);
}

// The potential file changed under a checkpoint: --resume refuses it by name (exit 2),
// and resumes once it is restored.
TEST(OutputFolder, AnInputFileChangedUnderTheCheckpointIsRefused) {
  fs::copy_file("/usr/share/lammps/potentials/Cu_mishin1.eam.alloy", kDir / "CuPinned.eam.alloy",
                fs::copy_options::overwrite_existing);
  const std::string deck = kDir.file("pinned.toml", R"([potential]
style = "eam"
file = "CuPinned.eam.alloy"
[lattice]
constant = 3.615
cells = [3, 3, 3]
[run]
dt = 0.002
steps = 60
thermo = 10
)");
  const fs::path out = kDir / "pinned";
  auto r = run_cli(fmt::format("md '{}' --quiet --threads 1 --out '{}' --stop-after 20", deck, out.string()));
  ASSERT_EQ(r.status, 130) << r.output;
  const fs::path pot = kDir / "CuPinned.eam.alloy";
  const std::string good = slurp(pot);
  std::string changed = good;
  changed[0] = changed[0] == 'X' ? 'Y' : 'X';  // a comment line: the file still reads
  std::ofstream(pot, std::ios::binary | std::ios::trunc) << changed;
  r = run_cli(fmt::format("md '{}' --quiet --threads 1 --out '{}' --resume", deck, out.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(fs::absolute(pot).lexically_normal().string() + " changed since the checkpoint"),
            std::string::npos)
      << r.output;
  std::ofstream(pot, std::ios::binary | std::ios::trunc) << good;
  r = run_cli(fmt::format("md '{}' --quiet --threads 1 --out '{}' --resume", deck, out.string()));
  EXPECT_EQ(r.status, 0) << r.output;
}

// A checkpoint of the format before the input files' digests is refused by its version.
TEST(OutputFolder, ACheckpointOfAnOlderFormatIsRefusedByItsVersion) {
  const fs::path cut = kDir / "old_format";
  auto r = run_cli(fmt::format("run '{}' {} --out '{}' --stop-after 100", kWave, kRun, cut.string()));
  ASSERT_EQ(r.status, 130) << r.output;
  std::string bytes = slurp(cut / "checkpoint.bin");
  bytes[16] = 2;  // the version, then the header's own CRC-32 made right again
  const std::uint32_t crc = mpmx::io::crc32_of(std::string_view(bytes).substr(0, 48));
  for (int b = 0; b < 4; ++b) bytes[48 + b] = static_cast<char>((crc >> (8 * b)) & 0xff);
  std::ofstream(cut / "checkpoint.bin", std::ios::binary | std::ios::trunc) << bytes;
  r = run_cli(fmt::format("run '{}' {} --out '{}' --resume", kWave, kRun, cut.string()));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("format version 2, this mpmx reads version 6"), std::string::npos) << r.output;
}

}  // namespace output_folder_test
