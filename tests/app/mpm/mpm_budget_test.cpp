// The continuum memory and work estimate at check time: a deck the machine cannot hold
// is refused by `mpmx check` and `mpmx run` with the key and the figure, --force or not;
// one that would run for more than a day is refused unless forced; the examples pass.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sys/wait.h>

#include <fmt/format.h>

#include "md/md_test_util.hpp"
#include "mpm/mpm_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/app/mpm/budget.hpp"
#include "cli_util.hpp"

namespace {

using namespace mpmx;

const char* k1d = R"([case]
id = "b"
[grid]
lower = 0.0
upper = 1.0
cells = CELLS
[particles]
per_cell = PER
[scheme]
name = "SCHEME"
SUB
[material]
model = "linear_elastic"
density = 1.0
youngs_modulus = 1.0
[initial.velocity]
profile = "sinusoid"
amplitude = 0.01
mode = 1
[boundary]
left = { type = "fixed" }
right = { type = "fixed" }
[time]
dt = DT
end = END
)";

std::string deck1d(const std::string& name, const std::string& cells, const std::string& per, const std::string& dt,
                   const std::string& end, const std::string& scheme = "mpm", const std::string& sub = "") {
  std::string t = k1d;
  for (auto [key, v] : {std::pair<std::string, std::string>{"CELLS", cells}, {"PER", per}, {"SCHEME", scheme},
                        {"SUB", sub}, {"DT", dt}, {"END", end}})
    t.replace(t.find(key), key.size(), v);
  return test::scratch_file(name, t).string();
}

struct Outcome {
  int code;
  std::string err, out;
};
Outcome mpmx_outcome(const std::string& args) {
  const std::string err = (test::scratch_root() / "budget_stderr").string();
  const std::string out = (test::scratch_root() / "budget_stdout").string();
  const int status = std::system(fmt::format("'{}' {} >'{}' 2>'{}'", MPMX_BINARY, args, out, err).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::slurp(err), test::slurp(out)};
}

TEST(MpmBudget, CountsPointsNodesAndSubpoints) {
  const auto c = app::read_mpm_deck(deck1d("count.toml", "50", "4", "1e-3", "1.0", "ddmp_subpoints", "subpoints = 8"));
  const auto b = app::estimate_mpm(c);
  EXPECT_EQ(b.points, 200);
  EXPECT_EQ(b.subpoints, 8);
  EXPECT_EQ(b.nodes, 51);
  EXPECT_EQ(b.steps, 1000);
  EXPECT_EQ(b.md_atoms, 0);
  EXPECT_GT(b.bytes, 200 * 8 * 8.0);
  EXPECT_NO_THROW(app::check_mpm_budget(b, physical_memory_bytes(), false));
}

TEST(MpmBudget, MemoryBeyondTheMachineIsRefusedEvenForced) {
  // 1e7 cells x 1e6 points per cell: each key in range, their product not.
  const std::string d = deck1d("mem.toml", "10000000", "1000000", "1e-8", "1e-6");
  for (const char* cmd : {"check", "check --force"}) {
    const auto r = mpmx_outcome(fmt::format("{} '{}'", cmd, d));
    EXPECT_EQ(r.code, 2) << cmd;
    EXPECT_NE(r.err.find("particles.per_cell and grid.cells: 1e+13 points"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("of memory"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(d + ": particles.per_cell"), std::string::npos) << r.err;  // the deck named
  }
  const auto r = mpmx_outcome(fmt::format("run --force --no-plot --quiet '{}' --out '{}'", d,
                                          (test::scratch_root() / "mem_out").string()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("of memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(test::scratch_root() / "mem_out"));
}

TEST(MpmBudget, MdBoxesBeyondTheMachineNameTheDeckAndTheRanks) {
  // The J2 jet at s = 0.1 with 20^3-cell boxes (32,000 atoms a point): 5e8 atoms.
  std::string t = test::slurp(test::example("J2_ddmp_md_100x50_4ppc_s0p1.toml"));
  t.replace(t.find("\ncells = 5"), 10, "\ncells = 20");
  t.replace(t.find("\"../data/"), 9, "\"" + std::string(MPMX_SOURCE_DIR) + "/data/");
  const std::string d = test::scratch_file("md_mem.toml", t).string();
  const auto r = mpmx_outcome(fmt::format("check '{}'", d));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(d + ": material.md.cells"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--ranks N"), std::string::npos) << r.err;
}

TEST(MpmBudget, SubpointsAndHugeGridsNameTheirKey) {
  // A 3-D grid of 1e13 cells, each axis in range.
  std::string t = fmt::format(R"([case]
id = "g"
[grid]
dim = 3
lower = [0.0, 0.0, 0.0]
upper = [1.0, 1.0, 1.0]
cells = [100000, 100000, 1000]
[particles]
per_cell = [1, 1, 1]
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
density = 1.0
youngs_modulus = 1.0
poisson_ratio = 0.0
[time]
dt = 1e-6
end = 1e-6
)");
  const auto r = mpmx_outcome(fmt::format("check '{}'", test::scratch_file("grid3.toml", t).string()));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("grid.cells"), std::string::npos) << r.err;
  // 2048 sub-points per point on a large bar.
  const auto s = mpmx_outcome(fmt::format(
      "check '{}'", deck1d("sub.toml", "10000000", "8", "1e-8", "1e-8", "ddmp_subpoints", "subpoints = 2048")));
  EXPECT_EQ(s.code, 2) << s.err;
  EXPECT_NE(s.err.find("scheme.subpoints"), std::string::npos) << s.err;
}

// A run refuses more than a day of work without --force; a check says so and passes (the
// deck may be a cluster's).
TEST(MpmBudget, MoreThanADayOfWorkNeedsForce) {
  const std::string d = deck1d("work.toml", "10", "1000000", "1e-3", "1e9");
  const auto r = mpmx_outcome(fmt::format("run '{}' --out '{}'", d, d + ".out"));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("time.end / time.dt"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  const auto c = mpmx_outcome(fmt::format("check '{}'", d));
  EXPECT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("more than a day of work on one core"), std::string::npos) << c.out;
  EXPECT_EQ(mpmx_outcome(fmt::format("check --force '{}'", d)).out.find("more than a day"), std::string::npos);
}

TEST(MpmBudget, EveryContinuumExamplePasses) {
  for (const char* name : {"A1_standing_wave_static.toml", "N5_two_spheres_mpm.toml", "H1_weak_0K_256.toml",
                           "N1_shock_tube_subpoints_2d.toml", "S1_mpm_1024ppc.toml"}) {
    const auto c = test::deck(test::example(name));
    EXPECT_NO_THROW(app::check_mpm_budget(app::estimate_mpm(c), physical_memory_bytes(), false)) << name;
  }
}

}  // namespace
