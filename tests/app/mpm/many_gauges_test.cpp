// ctest-cost: 1
// Gauges the file system would refuse are refused by the deck (a name too long for a
// file), and a run holds no file open per gauge: 2000 gauges run under a limit of 256
// open files, each table whole, and a stopped run resumed writes the same tables.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "cli_util.hpp"
#include "mpm_deck_test_util.hpp"

namespace {

namespace fs = std::filesystem;

// A 1-D bar hit by a piston, 20 steps, with `gauges` point gauges spread along it.
std::string bar_with_gauges(int gauges) {
  std::string text = R"(
[case]
id = "many_gauges"
units = "nm_ps_GPa"
[grid]
upper = 10.0
cells = 200
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
youngs_modulus = 130.0
density = 8.96
[boundary]
left = { type = "piston", velocity = 0.5 }
[output]
plot = false
[time]
dt = 1e-3
end = 2e-2
)";
  for (int k = 0; k < gauges; ++k) text += fmt::format("[[gauge]]\nname = \"g{}\"\nat = {}\n", k, 0.0025 + 0.005 * k);
  return text;
}

std::string deck_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(ManyGauges, ANameTooLongForAFileIsRefusedByTheDeck) {
  const std::string e = mpmx::test::mpm_deck_error(
      mpmx::test::replace(bar_with_gauges(1), "name = \"g0\"", "name = \"" + std::string(250, 'a') + "\""));
  EXPECT_HAS(e, "gauge");
  EXPECT_HAS(e, "is 250 characters long: at most 100 (it names the file gauge_<name>.csv)");
  EXPECT_EQ(mpmx::test::mpm_deck_error(
                mpmx::test::replace(bar_with_gauges(1), "name = \"g0\"", "name = \"" + std::string(100, 'a') + "\"")),
            "(no error)");
}

TEST(ManyGauges, TwoThousandGaugesRunUnderALimitOf256OpenFiles) {
  const std::string deck = deck_file("many_gauges.toml", bar_with_gauges(2000));
  const std::string out = ::testing::TempDir() + "many_gauges_out", cut = ::testing::TempDir() + "many_gauges_cut";
  fs::remove_all(out);
  fs::remove_all(cut);
  const auto r = mpmx::test::run_cli_env("ulimit -n 256 &&", "run " + deck + " -o " + out + " --quiet --no-plot");
  ASSERT_EQ(r.status, 0) << r.output;
  int tables = 0;
  for (const auto& e : fs::directory_iterator(out))
    if (e.path().filename().string().rfind("gauge_", 0) == 0) ++tables;
  EXPECT_EQ(tables, 2000);
  for (const char* g : {"gauge_g0.csv", "gauge_g999.csv", "gauge_g1999.csv"}) {
    const std::string t = mpmx::test::slurp(fs::path(out) / g);
    EXPECT_EQ(mpmx::test::count(t, "\n"), 22u) << g << "\n" << t;  // the header and steps 0 to 20
    EXPECT_EQ(t.rfind("step,time,x,vx,sigma_xx,density\n", 0), 0u) << t;
  }
  // Stopped at step 7 (a checkpoint) and resumed: the tables of the run without a stop.
  const auto stop = mpmx::test::run_cli_env("ulimit -n 256 &&",
                                            "run " + deck + " -o " + cut + " --quiet --no-plot --stop-after 7");
  ASSERT_EQ(stop.status, 130) << stop.output;
  const auto rest = mpmx::test::run_cli_env("ulimit -n 256 &&", "run " + deck + " -o " + cut + " --resume --quiet");
  ASSERT_EQ(rest.status, 0) << rest.output;
  EXPECT_HAS(rest.output, "20 steps (13 of them now, after --resume)");
  for (const char* g : {"gauge_g0.csv", "gauge_g1234.csv", "gauge_g1999.csv"})
    EXPECT_EQ(mpmx::test::slurp(fs::path(cut) / g), mpmx::test::slurp(fs::path(out) / g)) << g;
}
