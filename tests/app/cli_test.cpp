// The command line (issue 17): one exit-code table for every command (0 done, 1
// internal, 2 bad input, 3 stopped by the physics, 130 interrupted), unknown commands
// and flags named, bounded --threads, finite numbers, a non-empty --out, and each
// message printed once.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "mpmx/core/exit_codes.hpp"
#include "cli_util.hpp"

namespace {
using mpmx::test::count;
using Result = mpmx::test::CliResult;
constexpr auto mpmx_cli = mpmx::test::run_cli;

const std::string kDeck = std::string(MPMX_SOURCE_DIR) + "/examples/A1_standing_wave_moving.toml";
const std::string kMdDeck = std::string(MPMX_SOURCE_DIR) + "/examples/M1_cu_energy_vs_lattice.toml";

}  // namespace

TEST(Cli, ExitCodeTable) {
  EXPECT_EQ(mpmx::exit_code::done, 0);
  EXPECT_EQ(mpmx::exit_code::internal, 1);
  EXPECT_EQ(mpmx::exit_code::bad_input, 2);
  EXPECT_EQ(mpmx::exit_code::stopped, 3);
  EXPECT_EQ(mpmx::exit_code::interrupted, 130);
}

TEST(Cli, UnknownCommandIsNamed) {
  const auto r = mpmx_cli("frobnicate");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("unknown command 'frobnicate': expected one of run, check, md"), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("A subcommand is required"), std::string::npos) << r.output;
}

TEST(Cli, UnknownTopLevelOptionIsNamed) {
  for (const std::string args : {"--frob", "--frob run", "-x"}) {
    const auto r = mpmx_cli(args);
    EXPECT_EQ(r.status, 2) << r.output;
    const std::string word = args.substr(0, args.find(' '));
    EXPECT_NE(r.output.find("unknown option '" + word + "'"), std::string::npos) << r.output;
  }
}

TEST(Cli, NoCommandSaysWhichAreThere) {
  const auto r = mpmx_cli("");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("a command is required: one of run, check, md"), std::string::npos) << r.output;
}

TEST(Cli, UnknownFlagIsNamedWithExitCode2) {
  for (const std::string& args : {"md --bogus " + kMdDeck, "run --bogus " + kDeck, "check --frob " + kDeck}) {
    const auto r = mpmx_cli(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    const auto word = args.substr(args.find("--"), args.find(' ', args.find("--")) - args.find("--"));
    EXPECT_NE(r.output.find("The following argument was not expected: " + word), std::string::npos) << r.output;
    EXPECT_EQ(count(r.output, word), 1u) << r.output;
  }
}

TEST(Cli, HelpAndVersionExitZero) {
  EXPECT_EQ(mpmx_cli("--help").status, 0);
  EXPECT_EQ(mpmx_cli("md --help").status, 0);
  const auto v = mpmx_cli("--version");
  EXPECT_EQ(v.status, 0);
  EXPECT_NE(v.output.find("mpmx "), std::string::npos);
  EXPECT_NE(v.output.find("\nMPI: "), std::string::npos) << v.output;  // the library, or "none"
}

// libgomp's spinning waits would take a busy core's time from the thread they wait for:
// mpmx restarts itself with OMP_WAIT_POLICY=passive unless the user chose a policy.
TEST(Cli, IdleThreadsSleepUnlessTheUserChoseOtherwise) {
  auto version = [](const std::string& env) {
    return mpmx::test::run_cli_env(env, "--version").output;
  };
  EXPECT_NE(version("env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT").find("OMP_WAIT_POLICY=passive says"),
            std::string::npos);
  EXPECT_NE(version("env OMP_WAIT_POLICY=active").find("OMP_WAIT_POLICY=active says"), std::string::npos);
  EXPECT_NE(version("env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=1000").find("as GOMP_SPINCOUNT says"), std::string::npos);
  // The restarted program reads its arguments as the first did.
  const auto r = mpmx::test::run_cli_env("env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT", "run --threads -1 " + kDeck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--threads: -1 is negative"), std::string::npos) << r.output;
}

TEST(Cli, ThreadsAreBoundedByTheMachine) {
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const auto r = mpmx_cli("run --threads 100000 " + kDeck + " --out " + ::testing::TempDir() + "cli_threads");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(fmt::format("--threads: 100000 is too many: at most {} on this machine (4 x {} hardware "
                                      "threads)",
                                      4 * hw, hw)),
            std::string::npos)
      << r.output;
}

TEST(Cli, NegativeThreadsGetAShortMessage) {
  const auto r = mpmx_cli("run --threads -1 " + kDeck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--threads: -1 is negative: give 0 (all cores) or a count up to"), std::string::npos)
      << r.output;
  EXPECT_LT(r.output.size(), 200u) << r.output;  // not the 309-digit range of a double
  const auto x = mpmx_cli("run --threads 2.5 " + kDeck);
  EXPECT_EQ(x.status, 2) << x.output;
  EXPECT_NE(x.output.find("--threads: '2.5' is not a whole number"), std::string::npos) << x.output;
}

TEST(Cli, CheckpointMinutesMustBeFinite) {
  for (const char* v : {"nan", "inf", "NaN"}) {
    const auto r = mpmx_cli(std::string("run ") + kDeck + " --checkpoint-minutes " + v + " --out " +
                            ::testing::TempDir() + "cli_nan");
    EXPECT_EQ(r.status, 2) << v << r.output;
    EXPECT_NE(r.output.find(std::string("--checkpoint-minutes: ") + v + " is not a finite number"),
              std::string::npos)
        << r.output;
  }
  const auto r = mpmx_cli("run " + kDeck + " --checkpoint-minutes -5");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--checkpoint-minutes: -5 is negative"), std::string::npos) << r.output;
}

// Issue 31: --rebalance-above took nan, and -1's message printed the largest double.
TEST(Cli, RebalanceAboveMustBeFinite) {
  for (const std::string v : {"nan", "inf", "-1"}) {
    const auto r = mpmx_cli("run " + kDeck + " --rebalance-above=" + v + " --out " + ::testing::TempDir() + "cli_rb");
    EXPECT_EQ(r.status, 2) << v << r.output;
    EXPECT_NE(r.output.find("--rebalance-above: " + v + (v == "-1" ? " is negative" : " is not a finite number")),
              std::string::npos)
        << r.output;
    EXPECT_LT(r.output.size(), 200u) << r.output;
  }
}

TEST(Cli, EmptyOutIsRefused) {
  for (const std::string& cmd : {"md " + kMdDeck, "run " + kDeck}) {
    const auto r = mpmx_cli(cmd + " --out ''");
    EXPECT_EQ(r.status, 2) << cmd << r.output;
    EXPECT_NE(r.output.find("--out: the path is empty: give a directory"), std::string::npos) << r.output;
  }
}

TEST(Cli, InputErrorsArePrintedOnce) {
  const std::string dir = ::testing::TempDir() + "cli_once";
  std::FILE* f = std::fopen((::testing::TempDir() + "cli_once.toml").c_str(), "w");
  std::fputs("[potential]\nstyle = \"lj\"\nepsilon = 0.4\nsigma = 2.3\ncutoff = 5.0\nmass = 63.5\n"
             "[lattice]\nconstant = -3.6\ncells = [3]\n[run]\ndt = nan\nsteps = 1e3\n",
             f);
  std::fclose(f);
  const auto r = mpmx_cli("md " + ::testing::TempDir() + "cli_once.toml --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(count(r.output, "lattice.constant"), 1u) << r.output;
  EXPECT_EQ(count(r.output, "run.dt"), 1u) << r.output;
  EXPECT_EQ(count(r.output, "run.steps"), 1u) << r.output;
  EXPECT_EQ(count(r.output, "input error"), 1u) << r.output;
}

TEST(Cli, TemperaturesAreBounded) {
  // An MD deck at 1e30 K ran to completion with meaningless figures; every temperature
  // key now stops at 1e6 K, named, at check time.
  const std::string deck = ::testing::TempDir() + "cli_hot.toml";
  std::FILE* f = std::fopen(deck.c_str(), "w");
  std::fputs("[potential]\nstyle = \"lj\"\nepsilon = 0.4\nsigma = 2.3\ncutoff = 5.0\nmass = 63.5\n"
             "[lattice]\nconstant = 3.6\ncells = [3]\n[thermal]\ntemperature = 1e30\n[run]\ndt = 0.001\nsteps = 10\n",
             f);
  std::fclose(f);
  const auto r = mpmx_cli("md " + deck + " --check");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("thermal.temperature"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1e6 K"), std::string::npos) << r.output;
  const std::string dpd = std::string(MPMX_SOURCE_DIR) + "/examples/D_dpde_cu_nve.toml";
  const std::string hot = ::testing::TempDir() + "cli_hot_dpd.toml";
  std::FILE* in = std::fopen(dpd.c_str(), "r");
  std::string text;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, in)) text.append(buf, n);
  std::fclose(in);
  text.replace(text.find("initial_temperature = 596.0"), 27, "initial_temperature = 2e9");
  text.replace(text.find("cu_sc_298K_morse.toml"), 21, std::string(MPMX_SOURCE_DIR) + "/examples/cu_sc_298K_morse.toml");
  std::FILE* out = std::fopen(hot.c_str(), "w");
  std::fputs(text.c_str(), out);
  std::fclose(out);
  const auto d = mpmx_cli("dpd " + hot + " --check");
  EXPECT_EQ(d.status, 2) << d.output;
  EXPECT_NE(d.output.find("dpd.initial_temperature"), std::string::npos) << d.output;
}

namespace {

// Issue 31: `--out FILE` is an input error of every command (exit 2, a sentence), not a
// raw filesystem error (exit 1), and the file is left as it was.
TEST(Cli, OutThatIsAFileIsRefusedByEveryCommand) {
  const std::string file = ::testing::TempDir() + "cli_out_is_a_file";
  const std::string src = std::string(MPMX_SOURCE_DIR) + "/examples/";
  for (const std::string& cmd : {"run " + kDeck, "md " + kMdDeck, "dpd " + src + "D_dpd_equilibrium.toml",
                                 "fit-dpd " + src + "D0_md_to_dpd_fit.toml"}) {
    { std::ofstream(file) << "keep me\n"; }
    const auto r = mpmx_cli(cmd + " --out " + file);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("exists and is not a directory"), std::string::npos) << cmd << "\n" << r.output;
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "keep me") << cmd;
  }
}

}  // namespace

// One front door: `mpmx check` reads the deck's kind from its tables and runs that kind's
// check, with its estimate; a potential file is named as one.
TEST(Cli, CheckTakesEveryKindOfDeck) {
  const std::string ex = std::string(MPMX_SOURCE_DIR) + "/examples/";
  struct Case {
    const char* deck;
    int status;
    const char* says;
  };
  for (const Case& c : {Case{"M1_cu_energy_vs_lattice.toml", 0, "ok (md deck: 256 atoms"},
                        Case{"J1_direct_md_tiny.toml", 0, "atom-steps/s (a box of its potential timed"},
                        Case{"D1_flyer_dpd_only.toml", 0, "ok (dpd deck); 1.28e+04 particles"},
                        Case{"D1_flyer_grid_4A.toml", 0, "ok (dpd deck)"},
                        Case{"D0_md_to_dpd_fit.toml", 0, "ok (fit-dpd deck)"},
                        Case{"A1_standing_wave_moving.toml", 0, "ok (case A1"},
                        Case{"cu_sc_298K_morse.toml", 2, "a DPD potential file"}}) {
    const Result r = mpmx_cli("check " + ex + c.deck);
    EXPECT_EQ(r.status, c.status) << c.deck << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.deck << "\n" << r.output;
    EXPECT_EQ(r.output.find("is missing"), std::string::npos) << c.deck << "\n" << r.output;
  }
}
