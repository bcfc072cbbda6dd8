// ctest-cost: 1
// prepare = "npt" is the run's first work, not the deck reading's: Ctrl-C while its box
// runs ends the run cleanly (exit 130, saying so, its folder as it was), and the run's
// records are those of the deck prepared beforehand (tests/multiscale/md_closure_crystal_test.cpp).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cli_util.hpp"

namespace {

namespace fs = std::filesystem;

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

}  // namespace

TEST(NptAtStart, CtrlCWhileTheBoxIsPreparedEndsCleanly) {
  toml::table t = toml::parse_file(std::string(MPMX_SOURCE_DIR) + "/examples/H5_ta_110_small.toml");
  t.erase("reference");
  t["material"]["md"].as_table()->insert_or_assign("prepare_steps", 100000000);  // hours
  const std::string dir = ::testing::TempDir() + "npt_at_start";
  fs::remove_all(dir);
  fs::create_directories(dir + "/out");
  const std::string deck = dir + "/long_npt.toml", out = dir + "/out", script = dir + "/interrupt.sh";
  std::ofstream(deck) << t;
  std::ofstream(script) << fmt::format(
      "'{}' run '{}' --quiet --no-plot --threads 1 --out '{}' > /dev/null 2> '{}.stderr' &\npid=$!\n"
      "for i in $(seq 300); do [ -d '{}/.staging' ] && break; sleep 0.1; done\nsleep 1\nkill -INT $pid\nwait $pid\n",
      MPMX_BINARY, deck, out, out, out);
  const int status = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string err = mpmx::test::slurp(out + ".stderr");
  ASSERT_EQ(WEXITSTATUS(status), 130) << err;
  EXPECT_HAS(err, "interrupted: while the run was being prepared (md_closure's NPT box");
  EXPECT_HAS(err, "nothing to resume");
  EXPECT_TRUE(fs::is_empty(out));  // no .staging, no run.json, no checkpoint
}
