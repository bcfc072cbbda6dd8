// ctest-label: slow
// Ctrl-C on `mpmx run`: the run writes a checkpoint and exits 130; `--resume` then
// finishes with the same tables as a run never interrupted.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "multiscale/ms_test_util.hpp"

namespace {

using namespace mpmx;

TEST(Interrupt, CtrlCLeavesACheckpointThatResumesExactly) {
  const auto c = test::tiny_bar(4, 2, 400);
  const std::string deck = test::scratch_dir("interrupt") + "/tiny.toml";
  {
    std::ofstream f(deck);
    f << c.deck;
  }
  const std::string whole = test::scratch_dir("interrupt_whole"), cut = test::scratch_dir("interrupt_cut");
  const std::string run = fmt::format("'{}' run '{}' --quiet --no-plot --threads 2", MPMX_BINARY, deck);
  ASSERT_EQ(std::system(fmt::format("{} --out '{}' > /dev/null", run, whole).c_str()), 0);
  // SIGINT once the step loop runs (energy.csv appears, in the run's staging folder,
  // after the handler is set), then the exit status of the run.
  const std::string script = test::scratch_dir("interrupt_script") + "/interrupt.sh";
  {
    std::ofstream f(script);
    f << fmt::format("{} --out '{}' > /dev/null 2> '{}/stderr' &\npid=$!\nfor i in $(seq 300); do [ -s '{}/.staging/energy.csv' ] && break; sleep 0.1; done\nkill -INT $pid\nwait $pid\n",
                     run, cut, cut, cut);
  }
  const int status = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130) << test::read_file(cut + "/stderr");
  EXPECT_TRUE(std::filesystem::exists(cut + "/checkpoint.bin"));
  EXPECT_NE(test::read_file(cut + "/stderr").find("--resume"), std::string::npos);
  EXPECT_NE(test::read_file(cut + "/run.json").find("interrupted"), std::string::npos);
  ASSERT_EQ(std::system(fmt::format("{} --out '{}' --resume > /dev/null", run, cut).c_str()), 0);
  for (const char* f : {"particles.csv", "nodes.csv", "energy.csv"}) {
    const std::string a = test::read_file(whole + "/" + f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, test::read_file(cut + "/" + f)) << f;
  }
  EXPECT_FALSE(std::filesystem::exists(cut + "/checkpoint.bin"));
}

}  // namespace
