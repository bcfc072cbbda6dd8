// ctest-label: slow
// `mpmx md` of a [rod] deck (app/md/rod_run.hpp): the all-atom flyer-on-rod run records
// the region tracks of the DPD run's code in the DPD deck's frame, the impact's wave
// reaching a region no sooner than the longitudinal speed allows; stopped in the equilibration or in the run, `--resume` (on another
// thread count) ends with the same files; a [rod] beside a [jet] and bad [rod] values are
// refused by key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/interrupt_util.hpp"
#include "cli_util.hpp"
#include "md/md_test_util.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/multiscale/strained_box.hpp"

namespace {

namespace fs = std::filesystem;
using mpmx::test::json_number;
using mpmx::test::run_cli;
using mpmx::test::slurp;

const mpmx::test::ScratchFolder kRodDir("mpmx_rod_run");

// Mishin's copper: a rod of 16 x 4 x 4 cells hit by a 2-cell flyer; impact face at 7.23 A.
std::string rod_deck(const std::string& thermal, const std::string& rod_extra) {
  return R"([potential]
style = "eam"
file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.615
cells = [1, 1, 1]
)" + thermal + R"(
[run]
dt = 0.002
steps = 400
thermo = 50
[rod]
target_cells = [16, 4, 4]
flyer_cells = 2
flyer_velocity = 5.0
)" + rod_extra + R"(
[[track]]
name = "near"
x = [17.23, 23.23]
[[track]]
name = "far"
x = [37.23, 43.23]
[analysis]
every = 10
wave_speed = ["near", "far"]
[profile]
bins = 8
every = 100
)";
}

const std::string kWarm = rod_deck("[thermal]\ntemperature = 100.0\nseed = 4\n", "equilibrate_steps = 100\nrescale_every = 50\n");

}  // namespace

TEST(RodRun, TheImpactReachesTheNearRegionNoSoonerThanSoundAllows) {
  const std::string d = kRodDir.file("cold.toml", rod_deck("", "rescale_every = 0\n"));
  const fs::path out = kRodDir / "cold";
  const auto r = run_cli(fmt::format("md '{}' --quiet --threads 2 --out '{}'", d, out.string()));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string json = slurp(out / "run.json");
  // The near region starts 10 A past the impact face: no rise before sound at the
  // crystal's longitudinal speed sqrt(C11 / rho) could reach it (C11 of the potential's
  // static lattice). The far region meets the thin rod's contraction under its surface
  // stress first: its figures are not asserted.
  const mpmx::md::Potential pot(mpmx::test::copper_spec());
  const double a = 3.615;
  const double c11 = mpmx::multiscale::md_strained_constants(pot, a, {}).c11 / mpmx::units::eV_per_A3_in_GPa;
  const double rho = 4.0 * pot.mass(0) / (a * a * a);                        // amu/A^3
  const double longitudinal = std::sqrt(c11 / (rho * mpmx::units::mvv2e));   // A/ps
  ASSERT_GT(longitudinal, 40.0);  // Mishin Cu: C11 near 170 GPa
  ASSERT_LT(longitudinal, 47.0);
  const auto near_at = json.find("\"near\"");
  ASSERT_NE(near_at, std::string::npos);
  const double near_onset = json_number(json.substr(near_at), "onset_ps");
  EXPECT_GT(near_onset, 10.0 / longitudinal) << json;
  EXPECT_LT(near_onset, 0.8) << json;
  EXPECT_LT(json_number(json, "flyer_final_vx_A_per_ps"), 5.0);
  EXPECT_GT(json_number(json, "flyer_final_vx_A_per_ps"), 0.0);
  EXPECT_EQ(json_number(json, "flyer_atoms"), 4 * 2 * 4 * 4);
  EXPECT_EQ(slurp(out / "tracks.csv").substr(0, 68),
            "time_ps,near_ux_A,far_ux_A,near_vx_A_per_ps,far_vx_A_per_ps\n0.000000");
  EXPECT_TRUE(fs::exists(out / "profile.csv"));
}

TEST(RodRun, StoppedInTheEquilibrationOrTheRunResumesToTheSameFiles) {
  const std::string d = kRodDir.file("warm.toml", kWarm);
  const fs::path whole = kRodDir / "whole";
  ASSERT_EQ(run_cli(fmt::format("md '{}' --quiet --threads 2 --out '{}'", d, whole.string())).status, 0);
  EXPECT_NE(slurp(whole / "thermo.csv").find(",equilibrate,"), std::string::npos);
  for (const int at : {50, 250}) {
    const fs::path cut = kRodDir / fmt::format("cut{}", at);
    const auto stop = run_cli(fmt::format("md '{}' --quiet --threads 2 --out '{}' --stop-after {}", d, cut.string(), at));
    ASSERT_EQ(stop.status, 130) << stop.output;
    const auto r = run_cli(fmt::format("md '{}' --quiet --threads 1 --out '{}' --resume", d, cut.string()));
    ASSERT_EQ(r.status, 0) << r.output;
    mpmx::test::expect_same_folders(whole, cut);
  }
}

TEST(RodRun, BadRodDecksAreRefusedByKey) {
  auto refused = [](const std::string& name, const std::string& text, const std::string& key) {
    const std::string d = kRodDir.file(name, text);
    const auto r = run_cli(fmt::format("md '{}' --check", d));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find(key), std::string::npos) << r.output;
  };
  auto with = [](std::string text, const std::string& from, const std::string& to) {
    return text.replace(text.find(from), from.size(), to);
  };
  refused("v0.toml", with(kWarm, "flyer_velocity = 5.0", "flyer_velocity = 0.0"), "rod.flyer_velocity");
  refused("eq.toml", with(kWarm, "equilibrate_steps = 100", "equilibrate_steps = 120"), "rod.equilibrate_steps");
  refused("cold.toml", with(kWarm, "temperature = 100.0", "temperature = 0.0"), "rod.rescale_every");
  refused("empty.toml", with(kWarm, "x = [37.23, 43.23]", "x = [237.23, 243.23]"), "track \"far\"");
  refused("jet.toml", kWarm + "[jet]\ncells = [400, 200, 4]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                              "bins = [20, 5]\nduration_ps = 1.0\nrecord_every_ps = 0.5\n", "one of [bar], [jet] and [rod]");
}
