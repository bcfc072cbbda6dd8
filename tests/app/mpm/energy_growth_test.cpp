// Right by default: a deck that names no velocity update gets a stable one (MUSL), and a
// run whose total energy grows is told so (status "energy_growth") or stopped.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "app/mpm/disk_on_wall.hpp"
#include "mpm/mpm_test_util.hpp"
#include "mpmx/core/error.hpp"

using namespace mpmx;

namespace {

// An elastic disk thrown at a fixed wall, as a user writes it from the guide: no
// update_velocity line. The seed's midpoint form grows its energy without bound here
// (1.9x by t = 5).
using test::kDiskOnWall;

app::MpmConfig disk_on_wall(const std::string& extra_time = "", const std::string& update = "") {
  std::string text = kDiskOnWall;
  if (!update.empty()) text.replace(text.find("name = \"mpm\""), 12, "name = \"mpm\"\nupdate_velocity = \"" + update + "\"");
  if (!extra_time.empty()) text.replace(text.find("end = 5.0"), 9, "end = 5.0\n" + extra_time);
  return app::read_mpm_deck_text(text, "disk_on_wall.toml");
}

}  // namespace

TEST(DefaultUpdate, IsMuslAndKeepsTheDiskOnAWallWithinTwoPercent) {
  const auto c = disk_on_wall();
  EXPECT_TRUE(c.scheme.musl);
  EXPECT_FALSE(c.scheme.midpoint_gradient);
  const auto r = test::run_dim<2>(c);
  ASSERT_EQ(r.steps, 500);
  ASSERT_TRUE(std::isfinite(r.energy_growth));
  EXPECT_LT(std::abs(r.energy_growth), 0.02);  // measured +0.30%
  EXPECT_FALSE(r.energy_grew);
}

TEST(DefaultUpdate, KeepsN3sEnergyWithinOnePercent) {
  // N3 without its update_velocity line.
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"),
                                 [](toml::table& t) { t["scheme"].as_table()->erase("update_velocity"); });
  EXPECT_TRUE(c.scheme.musl);
  const auto r = test::run_dim<2>(c);
  const double e0 = r.kinetic_initial + r.stored_initial, e1 = r.kinetic_final + r.stored_final;
  EXPECT_LT(std::abs(e1 - e0) / e0, 0.01);  // measured -0.77% (midpoint +3.8%, updated -7.9%)
}

TEST(EnergyGrowth, PastTheLimitTheRunEndsWithTheStatus) {
  // The midpoint form on the same disk, to t = 5 but stopping only at 20x: it ends with a
  // growth above time.energy_growth and says so.
  const auto c = disk_on_wall("energy_growth = 0.1\nenergy_growth_stop = 20.0", "midpoint");
  const std::string out = (std::filesystem::temp_directory_path() / "mpmx_energy_growth_end").string();
  std::filesystem::remove_all(out);
  app::RunOptions o;
  o.quiet = true, o.plot = false, o.out_dir = out;
  const auto r = app::run_mpm_dim<2>(c, o);
  EXPECT_EQ(r.steps, 500);
  EXPECT_GT(r.energy_growth, 0.1);
  EXPECT_TRUE(r.energy_grew);
  const std::string json = test::slurp(out + "/run.json");
  EXPECT_NE(json.find("\"status\" : \"energy_growth\""), std::string::npos) << json.substr(0, 400);
  EXPECT_NE(json.find("\"growth\""), std::string::npos);
  std::filesystem::remove_all(out);
}

TEST(EnergyGrowth, PastTheStopTheRunStopsWithTheStepAndTheFigure) {
  const auto c = disk_on_wall("energy_growth = 0.05\nenergy_growth_stop = 0.2", "midpoint");
  const std::string out = (std::filesystem::temp_directory_path() / "mpmx_energy_growth_stop").string();
  std::filesystem::remove_all(out);
  app::RunOptions o;
  o.quiet = true, o.plot = false, o.out_dir = out;
  try {
    app::run_mpm_dim<2>(c, o);
    FAIL() << "the run should have stopped";
  } catch (const RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("energy growth at step"), std::string::npos) << what;
    EXPECT_NE(what.find("time.energy_growth_stop = 0.2"), std::string::npos) << what;
  }
  const std::string json = test::slurp(out + "/run.json");
  EXPECT_NE(json.find("\"status\" : \"energy_growth\""), std::string::npos) << json.substr(0, 400);
  std::filesystem::remove_all(out);
}

TEST(EnergyGrowth, LimitsAreCheckedByKey) {
  EXPECT_THROW(disk_on_wall("energy_growth = -1.0"), InputError);
  EXPECT_THROW(disk_on_wall("energy_growth = 0.5\nenergy_growth_stop = 0.2"), InputError);
  const auto c = disk_on_wall("energy_growth = 0.5");
  EXPECT_DOUBLE_EQ(c.energy_growth, 0.5);
  EXPECT_DOUBLE_EQ(c.energy_growth_stop, 1.0);
}
