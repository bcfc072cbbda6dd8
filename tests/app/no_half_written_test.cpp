// Nothing half-written: a run into a folder that holds an earlier finished run never
// damages it. A run refused at start leaves the folder byte for byte as it was (and
// creates none); a run the physics stops replaces it with a consistent partial result;
// anything else that ends a run midway leaves the earlier files untouched.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

#include <fmt/format.h>

#include "../md/md_test_util.hpp"
#include "app/interrupt_util.hpp"
#include "mpmx/io/staged_dir.hpp"

namespace {

using namespace mpmx;
namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

using test::snapshot;

int mpmx(const std::string& args) {
  const int status = std::system(fmt::format("'{}' {} >/dev/null 2>&1", MPMX_BINARY, args).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const char* kBar = R"([case]
id = "bar"
[grid]
lower = 0.0
upper = 1.0
cells = 20
[particles]
per_cell = 2
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
density = 1.0
youngs_modulus = 1.0
[initial.velocity]
profile = "sinusoid"
amplitude = AMPLITUDE
mode = 1
[boundary]
left = { type = "fixed" }
right = { type = "fixed" }
[time]
dt = 1e-3
end = 0.2
)";

std::string bar_deck(const std::string& name, const std::string& amplitude, const std::string& extra = "") {
  std::string t = kBar;
  t.replace(t.find("AMPLITUDE"), 9, amplitude);
  return test::scratch_file(name, t + extra).string();
}

TEST(NoHalfWritten, ContinuumRunRefusedAtStartLeavesTheEarlierRun) {
  const fs::path out = test::scratch_root() / "cont_out";
  ASSERT_EQ(mpmx(fmt::format("run '{}' --out '{}' --quiet --no-plot", bar_deck("ok.toml", "0.01"), out.string())), 0);
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("run.json") && before.count("nodes.csv"));
  // A reference file that does not exist: refused, nothing touched.
  const std::string bad = bar_deck("bad.toml", "0.01", "[reference]\nname = \"standing_wave\"\nfile = \"nope.csv\"\n");
  EXPECT_EQ(mpmx(fmt::format("run '{}' --out '{}' --quiet --no-plot", bad, out.string())), 2);
  EXPECT_EQ(snapshot(out), before);
  // Into a folder that does not exist: none is created.
  const fs::path fresh = test::scratch_root() / "cont_fresh";
  EXPECT_EQ(mpmx(fmt::format("run '{}' --out '{}' --quiet --no-plot", bad, fresh.string())), 2);
  EXPECT_FALSE(fs::exists(fresh));
}

TEST(NoHalfWritten, ContinuumRunStoppedByThePhysicsLeavesAConsistentResult) {
  const fs::path out = test::scratch_root() / "cont_stop";
  ASSERT_EQ(mpmx(fmt::format("run '{}' --out '{}' --quiet --no-plot", bar_deck("ok2.toml", "0.01"), out.string())), 0);
  // Another deck into the folder: let in by --overwrite.
  EXPECT_EQ(mpmx(fmt::format("run '{}' --out '{}' --quiet --no-plot --overwrite", bar_deck("boom.toml", "1e300"),
                             out.string())),
            3);
  const auto after = snapshot(out);
  EXPECT_NE(after.at("run.json").find("\"stopped\""), std::string::npos);
  EXPECT_FALSE(fs::exists(out / ".staging"));
  // The tables are the stopped run's own: their last step is no later than the stop.
  EXPECT_EQ(after.at("energy.csv").find("\n200,"), std::string::npos);
}

TEST(NoHalfWritten, MdRunRefusedAtStartLeavesTheEarlierRun) {
  const std::string deck = R"([potential]
style = "eam"
file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy"
elements = ["ELEMENT"]
[lattice]
type = "fcc"
constant = 3.615
cells = [2, 2, 2]
[run]
dt = 0.001
steps = 10
thermo = 5
)";
  auto with = [&](const std::string& name, const std::string& element) {
    std::string t = deck;
    t.replace(t.find("ELEMENT"), 7, element);
    return test::scratch_file(name, t).string();
  };
  const fs::path out = test::scratch_root() / "md_out";
  ASSERT_EQ(mpmx(fmt::format("md '{}' --out '{}' --quiet", with("md_ok.toml", "Cu"), out.string())), 0);
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("run.json") && before.count("thermo.csv"));
  EXPECT_EQ(mpmx(fmt::format("md '{}' --out '{}' --quiet", with("md_bad.toml", "Xx"), out.string())), 2);
  EXPECT_EQ(snapshot(out), before);
  const fs::path fresh = test::scratch_root() / "md_fresh";
  EXPECT_EQ(mpmx(fmt::format("md '{}' --out '{}' --quiet", with("md_bad2.toml", "Xx"), fresh.string())), 2);
  EXPECT_FALSE(fs::exists(fresh));
}

TEST(NoHalfWritten, DpdRunRefusedAtStartLeavesTheEarlierRun) {
  const std::string deck = R"([case]
id = "d"
[potential]
style = "dpd"
a = 0.064631
cutoff = 10.0
[[block]]
lattice = "random"
count = 60
size = [20.0, 20.0, 20.0]
mass = 100.0
[box]
size = [20.0, 20.0, 20.0]
boundary = ["p", "p", "p"]
[dpd]
ensemble = "dpd"
integrator = "velocity_verlet"
gamma = 71.07
temperature = 300.0
seed = 1
[run]
dt = DT
steps = 10
thermo = 5
)";
  auto with = [&](const std::string& name, const std::string& dt) {
    std::string t = deck;
    t.replace(t.find("DT"), 2, dt);
    return test::scratch_file(name, t).string();
  };
  const fs::path out = test::scratch_root() / "dpd_out";
  ASSERT_EQ(mpmx(fmt::format("dpd '{}' --out '{}' --quiet", with("dpd_ok.toml", "0.06"), out.string())), 0);
  const auto before = snapshot(out);
  ASSERT_TRUE(before.count("run.json"));
  EXPECT_EQ(mpmx(fmt::format("dpd '{}' --out '{}' --quiet", with("dpd_bad.toml", "-1.0"), out.string())), 2);
  EXPECT_EQ(snapshot(out), before);
}

// A failure that is neither bad input nor the physics (out of memory, a bug) midway
// through writing: the earlier files stay; a stop by the physics publishes.
TEST(NoHalfWritten, StagedRunPublishesOnlyARunThatEnded) {
  const fs::path out = test::scratch_root() / "staged";
  fs::create_directories(out);
  std::ofstream(out / "run.json") << "earlier";
  EXPECT_THROW(io::run_staged(out.string(),
                              [](const std::string& dir) -> int {
                                fs::create_directories(dir);
                                std::ofstream(fs::path(dir) / "run.json") << "half";
                                throw std::runtime_error("midway");
                              }),
               std::runtime_error);
  EXPECT_EQ(read(out / "run.json"), "earlier");
  EXPECT_FALSE(fs::exists(out / ".staging"));
  try {
    io::run_staged(out.string(), [](const std::string& dir) -> int {
      fs::create_directories(dir);
      std::ofstream(fs::path(dir) / "run.json") << "stopped";
      throw RunError("stopped (partial results in " + dir + ")");
    });
    FAIL() << "no RunError";
  } catch (const RunError& e) {
    EXPECT_EQ(std::string(e.what()), "stopped (partial results in " + out.string() + ")");
  }
  EXPECT_EQ(read(out / "run.json"), "stopped");
  // A folder made for a run that wrote nothing is removed.
  const fs::path none = test::scratch_root() / "staged_none";
  EXPECT_THROW(io::run_staged(none.string(),
                              [](const std::string& dir) -> int {
                                fs::create_directories(dir);
                                throw InputError("late");
                              }),
               InputError);
  EXPECT_FALSE(fs::exists(none));
}

}  // namespace

namespace {

TEST(NoHalfWritten, LammpsRouteWritesThroughTheStagingFolder) {
  // `md --lammps-write-only` into the folder of a finished mpmx run: the LAMMPS inputs
  // join it, the run's own files stay, and no staging folder is left; a deck with no bar
  // or jet is refused before anything is made.
  const std::string deck = std::string(MPMX_SOURCE_DIR) + "/examples/J1_direct_md_tiny.toml";
  const fs::path out = test::scratch_root() / "lammps_out";
  ASSERT_EQ(mpmx(fmt::format("md '{}' --out '{}' --quiet", deck, out.string())), 0);
  const auto before = snapshot(out);
  ASSERT_EQ(mpmx(fmt::format("md '{}' --out '{}' --lammps-write-only", deck, out.string())), 0);
  const auto after = snapshot(out);
  for (const auto& [name, bytes] : before) {
    if (name == ".mpmx-files") continue;  // the list gains lammps/
    EXPECT_EQ(after.at(name), bytes) << name;
  }
  EXPECT_NE(after.at(".mpmx-files").find("lammps/in.jet"), std::string::npos);
  EXPECT_TRUE(after.count("lammps/in.jet") && after.count("lammps/jet.data"));
  EXPECT_FALSE(fs::exists(out / ".staging"));
  const fs::path fresh = test::scratch_root() / "lammps_fresh";
  const std::string m1 = std::string(MPMX_SOURCE_DIR) + "/examples/M1_cu_energy_vs_lattice.toml";
  EXPECT_EQ(mpmx(fmt::format("md '{}' --out '{}' --lammps-write-only", m1, fresh.string())), 2);
  EXPECT_FALSE(fs::exists(fresh));
}

}  // namespace
