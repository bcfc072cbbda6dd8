// ctest-label: slow
// Ctrl-C on `mpmx run`, or SIGTERM to it (kill's default, a batch system's time limit),
// one process: the run writes a checkpoint and exits 130; `--resume` then finishes with
// the same tables as a run never interrupted.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "multiscale/ms_test_util.hpp"

namespace {

using namespace mpmx;

// The tiny bar's run whole, then signalled with `signal` once its step loop runs and
// resumed: the same tables.
void interrupt_tiny_bar(const std::string& name, const std::string& signal) {
  const auto c = test::tiny_bar(4, 2, 400);
  const std::string deck = test::scratch_dir(name) + "/tiny.toml";
  {
    std::ofstream f(deck);
    f << c.deck;
  }
  const std::string whole = test::scratch_dir(name + "_whole"), cut = test::scratch_dir(name + "_cut");
  const std::string run = fmt::format("'{}' run '{}' --quiet --no-plot --threads 2", MPMX_BINARY, deck);
  ASSERT_EQ(std::system(fmt::format("{} --out '{}' > /dev/null", run, whole).c_str()), 0);
  // The signal once the step loop runs (energy.csv appears, in the run's staging folder,
  // after the handler is set), then the exit status of the run.
  const std::string script = test::scratch_dir(name + "_script") + "/interrupt.sh";
  {
    std::ofstream f(script);
    f << fmt::format("{} --out '{}' > /dev/null 2> '{}/stderr' &\npid=$!\nfor i in $(seq 300); do [ -s '{}/.staging/energy.csv' ] && break; sleep 0.1; done\nkill -{} $pid\nwait $pid\n",
                     run, cut, cut, cut, signal);
  }
  const int status = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 130) << test::read_file(cut + "/stderr");
  EXPECT_TRUE(std::filesystem::exists(cut + "/checkpoint.bin"));
  EXPECT_FALSE(std::filesystem::exists(cut + "/.staging"));
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

TEST(Interrupt, CtrlCLeavesACheckpointThatResumesExactly) { interrupt_tiny_bar("interrupt", "INT"); }

TEST(Interrupt, SigtermToOneProcessLeavesACheckpointThatResumesExactly) {
  interrupt_tiny_bar("interrupt_term", "TERM");
}

// Ctrl-C while md_closure builds its boxes (before any step, so no state to keep): the
// run says so and exits 130 at once, leaving its folder as it was (here: empty). It used
// to die of the signal with no word and OUT/.staging left behind.
TEST(Interrupt, CtrlCWhileTheBoxesAreBuiltEndsCleanly) {
  auto c = test::tiny_bar(16, 3, 10, 300.0);
  c.deck["material"]["md"].as_table()->insert_or_assign("relax_steps", 50000);  // about 20 s of building
  const std::string deck = test::scratch_dir("interrupt_build") + "/tiny.toml";
  std::ofstream(deck) << c.deck;
  const std::string cut = test::scratch_dir("interrupt_build_cut");
  const std::string script = test::scratch_dir("interrupt_build_script") + "/interrupt.sh";
  std::ofstream(script) << fmt::format(
      "'{}' run '{}' --quiet --no-plot --threads 2 --out '{}' > /dev/null 2> '{}.stderr' &\npid=$!\n"
      "for i in $(seq 300); do [ -d '{}/.staging' ] && break; sleep 0.1; done\nsleep 1\nkill -INT $pid\nwait $pid\n",
      MPMX_BINARY, deck, cut, cut, cut);
  const int status = std::system(("bash '" + script + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  const std::string err = test::read_file(cut + ".stderr");
  ASSERT_EQ(WEXITSTATUS(status), 130) << err;
  EXPECT_NE(err.find("interrupted: while the MD boxes were being built"), std::string::npos) << err;
  EXPECT_NE(err.find("nothing to resume"), std::string::npos) << err;
  EXPECT_TRUE(std::filesystem::is_empty(cut));  // no .staging, no run.json, no checkpoint
}

}  // namespace
