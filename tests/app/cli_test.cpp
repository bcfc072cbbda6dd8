// The command line (issue 17): one exit-code table for every command (0 done, 1
// internal, 2 bad input, 3 stopped by the physics, 130 interrupted), unknown commands
// and flags named, bounded --threads, finite numbers, a non-empty --out, and each
// message printed once; the common options on every command, a deck given to the wrong
// command, [case] and its units in every deck kind, the unit slips `check` warns of, a
// funcfl file's element, and what the run says of itself (the axis, step and time a point
// left the grid by; the steps a dt = "cfl" run and a resumed md run took).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
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

namespace {

const std::string kExamples = std::string(MPMX_SOURCE_DIR) + "/examples/";

// A deck written to the test's temporary folder; its path.
std::string deck_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// A text with every `from` in it replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

// A 108-atom Cu box, 200 steps: an md deck that runs in a moment.
const std::string kSmallMd = R"([potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]

[lattice]
type = "fcc"
constant = 3.615
cells = [3, 3, 3]

[thermal]
temperature = 300.0
seed = 12345

[run]
dt = 0.001
steps = 200
ensemble = "nve"
thermo = 50
)";

}  // namespace

// -o/--out, -j/--threads, --resume, -q/--quiet, --no-plot and --check on every command:
// accepted, and where one cannot apply, said to be ignored (one line each), never refused.
TEST(Cli, EveryCommandTakesTheCommonOptions) {
  const std::string out = ::testing::TempDir() + "cli_common_options";
  const std::string common = " -o " + out + " -j 1 --resume -q --no-plot --check";
  for (const std::string& cmd : {"run " + kDeck, "md " + kMdDeck, "dpd " + kExamples + "D_dpd_equilibrium.toml",
                                 "fit-dpd " + kExamples + "D0_md_to_dpd_fit.toml", "check " + kDeck}) {
    const auto r = mpmx_cli(cmd + common);
    EXPECT_EQ(r.status, 0) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find(": ok ("), std::string::npos) << cmd << "\n" << r.output;
    for (const char* option : {"--out", "--threads", "--resume", "--quiet", "--no-plot"})
      EXPECT_EQ(count(r.output, fmt::format(": {} ignored: a check", option)), 1u) << cmd << "\n" << r.output;
    EXPECT_FALSE(std::filesystem::exists(out)) << cmd;
  }
  // The new user's command line: an md run with -o and -j, the short forms `run` takes.
  const auto r = mpmx_cli("md " + kMdDeck + " -o " + out + " -j 1 -q --no-plot");
  EXPECT_EQ(r.status, 0) << r.output;
  // M1's [scan] draws its figure: --no-plot applies, and leaves it out.
  EXPECT_EQ(r.output.find("--no-plot ignored"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out + "/energy_vs_lattice.png"));
  const std::string json = mpmx::test::slurp(out + "/run.json");
  EXPECT_NE(json.find("\"case\" : \"M1_cu_energy_vs_lattice\""), std::string::npos) << json;
  std::filesystem::remove_all(out);
  if (std::system("/usr/bin/python3 -c 'import matplotlib, numpy' >/dev/null 2>&1") == 0) {
    EXPECT_EQ(mpmx_cli("md " + kMdDeck + " -o " + out + " -j 1 -q").status, 0);
    EXPECT_TRUE(std::filesystem::exists(out + "/energy_vs_lattice.png"));  // the E(a) curve
    std::filesystem::remove_all(out);
  }
}

// A deck given to the wrong command: one sentence naming the command that runs it (exit 2),
// not the keys that command's reader does not know; `check` says the command too.
TEST(Cli, DeckOfAnotherKindNamesItsCommand) {
  struct Case {
    std::string command, deck, kind, runs_it;
  };
  for (const Case& c : {Case{"run", kMdDeck, "an md deck", "mpmx md"},
                        Case{"md", kDeck, "a continuum deck", "mpmx run"},
                        Case{"dpd", kExamples + "D0_md_to_dpd_fit.toml", "a fit-dpd deck", "mpmx fit-dpd"},
                        Case{"fit-dpd", kExamples + "D_dpd_equilibrium.toml", "a dpd deck", "mpmx dpd"},
                        Case{"run", kExamples + "D_dpd_equilibrium.toml", "a dpd deck", "mpmx dpd"}}) {
    const auto r = mpmx_cli(c.command + " " + c.deck + " -o " + ::testing::TempDir() + "cli_wrong_command");
    EXPECT_EQ(r.status, 2) << c.command << " " << c.deck << "\n" << r.output;
    EXPECT_NE(r.output.find(c.deck + " is " + c.kind), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("run it with `" + c.runs_it + " " + c.deck + "`, not `mpmx " + c.command + "`"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("unknown key"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("is missing"), std::string::npos) << r.output;
  }
  const auto r = mpmx_cli("check " + kMdDeck);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("md deck: run it with `mpmx md " + kMdDeck + "`"), std::string::npos) << r.output;
}

// [case] in every deck kind, and one rule for case.units: a known system by name, or
// "dimensionless ..." for a continuum deck; md, dpd and fit-dpd decks are in metal units.
TEST(Cli, CaseAndItsUnitsInEveryDeckKind) {
  const std::string potential = "file = \"/usr/share/lammps/potentials/Cu_mishin1.eam.alloy\"";
  const std::string md = replaced(kSmallMd, "file = \"Cu_mishin1.eam.alloy\"", potential);
  {
    const auto r = mpmx_cli("check " + deck_file("cli_md_case.toml", "[case]\nid = \"cu108\"\ntitle = \"a box\"\n"
                                                                       "seed = \"x\"\nunits = \"metal\"\n\n" + md));
    EXPECT_EQ(r.status, 0) << r.output;
  }
  {
    const auto r = mpmx_cli("md --check " + deck_file("cli_md_units.toml", "[case]\nunits = \"nm_ps_GPa\"\n\n" + md));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("'case.units' = \"nm_ps_GPa\": this kind of deck is in metal units"), std::string::npos)
        << r.output;
  }
  for (const std::string name : {"D_dpd_equilibrium.toml", "D0_md_to_dpd_fit.toml"}) {
    const std::string text = mpmx::test::slurp(kExamples + name);
    const std::string in_si = deck_file("cli_si_" + name, replaced(text, "[case]\n", "[case]\nunits = \"SI\"\n"));
    const auto r = mpmx_cli("check " + in_si);
    EXPECT_EQ(r.status, 2) << name << "\n" << r.output;
    EXPECT_NE(r.output.find("'case.units' = \"SI\": this kind of deck is in metal units"), std::string::npos)
        << r.output;
    const std::string in_metal =
        deck_file("cli_metal_" + name, replaced(text, "[case]\n", "[case]\nunits = \"metal\"\n"));
    EXPECT_EQ(mpmx_cli("check " + in_metal).status, 0) << name;
  }
  const std::string a1 = mpmx::test::slurp(kDeck);
  ASSERT_NE(a1.find("units = \"dimensionless"), std::string::npos);
  for (const std::string units : {"nm_ps_Gpa", "consistent units", "furlongs"}) {
    const std::string text = std::regex_replace(a1, std::regex("units = \"[^\"]*\""), "units = \"" + units + "\"");
    const auto r = mpmx_cli("check " + deck_file("cli_units.toml", text));
    EXPECT_EQ(r.status, 2) << units << "\n" << r.output;
    EXPECT_NE(r.output.find("'case.units' = \"" + units + "\": not a known unit system: give one of nm_ps_GPa, "
                            "mm_us_GPa, metal, SI, or \"dimensionless\""),
              std::string::npos)
        << r.output;
  }
  for (const std::string units : {"nm_ps_GPa", "SI", "dimensionless", "dimensionless (c = 1)"}) {
    const std::string text = std::regex_replace(a1, std::regex("units = \"[^\"]*\""), "units = \"" + units + "\"");
    EXPECT_EQ(mpmx_cli("check " + deck_file("cli_units.toml", text)).status, 0) << units;
  }
}

// `check` warns (exit 0) of a velocity, density or modulus no solid has in the deck's
// units, naming the likely slip; the same deck in the right units gets no warning.
TEST(Cli, CheckWarnsOfUnitSlips) {
  const std::string deck = R"([case]
id = "slip"
units = "nm_ps_GPa"

[grid]
upper = 20.0
cells = 20

[particles]
per_cell = 2

[scheme]
name = "mpm"

[material]
model = "linear_elastic"
youngs_modulus = 169.878e9
density = 8935.577

[initial.velocity]
profile = "uniform"
value = 1000.0

[boundary]
left = { type = "fixed" }
right = { type = "fixed" }

[time]
dt = 0.0001
end = 0.001
)";
  const auto r = mpmx_cli("check " + deck_file("cli_slips.toml", deck));
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* slip : {"warning: [material] density = 8935.58 in nm_ps_GPa is 8.94e+06 kg/m^3, far above",
                           ": kg/m^3 typed for g/cm^3? (8.93558 would be 8.94e+03 kg/m^3)",
                           "warning: [material] uniaxial modulus = 1.69878e+11 in nm_ps_GPa is 1.7e+20 Pa",
                           ": Pa typed for GPa? (169.878 would be 1.7e+11 Pa)",
                           "warning: initial.velocity = 1000 in nm_ps_GPa is 1e+06 m/s",
                           ": m/s typed for km/s? (1 would be 1e+03 m/s)"})
    EXPECT_NE(r.output.find(slip), std::string::npos) << slip << "\n" << r.output;
  const std::string right =
      replaced(replaced(replaced(deck, "169.878e9", "169.878"), "8935.577", "8.935577"), "1000.0", "1.0");
  const auto ok = mpmx_cli("check " + deck_file("cli_no_slips.toml", right));
  EXPECT_EQ(ok.status, 0) << ok.output;
  EXPECT_EQ(ok.output.find("warning"), std::string::npos) << ok.output;
}

// A funcfl file names no element: its line 2's atomic number must be the deck's element's.
TEST(Cli, FuncflElementMustMatchTheFile) {
  const std::string ni = "/usr/share/lammps/potentials/Ni_u3.eam";
  if (!std::filesystem::exists(ni)) GTEST_SKIP() << ni << " is not installed";
  const std::string md = replaced(kSmallMd, "file = \"Cu_mishin1.eam.alloy\"", "file = \"" + ni + "\"");
  const auto r = mpmx_cli("md --check " + deck_file("cli_funcfl_cu.toml", md));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("element 'Cu' (atomic number 29) is not that of " + ni +
                          ", whose line 2 gives atomic number 28 (Ni)"),
            std::string::npos)
      << r.output;
  const auto bad = mpmx_cli("md --check " + deck_file("cli_funcfl_xx.toml", replaced(md, "[\"Cu\"]", "[\"cu\"]")));
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("'cu' is not an element symbol"), std::string::npos) << bad.output;
  const auto ok = mpmx_cli("md --check " + deck_file("cli_funcfl_ni.toml", replaced(md, "[\"Cu\"]", "[\"Ni\"]")));
  EXPECT_EQ(ok.status, 0) << ok.output;
}

// A point that leaves the grid is named with its axis, the step and the time (exit 3).
TEST(Cli, LeftTheGridNamesAxisStepAndTime) {
  std::string deck = mpmx::test::slurp(kExamples + "N3_two_disks_ddmp.toml");
  deck = replaced(deck, "velocity = [0.1, 0.1]", "velocity = [0.0, 2.0]");
  const std::string out = ::testing::TempDir() + "cli_left_grid";
  const auto r = mpmx_cli("run " + deck_file("cli_left_grid.toml", deck) + " -o " + out + " -q --no-plot --overwrite");
  EXPECT_EQ(r.status, 3) << r.output;
  EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(left the grid \(y = [0-9.e+-]+, more than a cell past the )"
                                                     R"(grid's upper y end\) in step [0-9]+ \(t = [0-9.e+-]+\))")))
      << r.output;
  // Its last state written as the final record, said in run.json.
  const std::string json = mpmx::test::slurp(out + "/run.json");
  EXPECT_NE(json.find("\"final_record\""), std::string::npos) << json;
  EXPECT_NE(mpmx::test::slurp(out + "/particles.pvd").find("vtk/particles_final_"), std::string::npos);
  std::filesystem::remove_all(out);
}

// With dt = "cfl" the progress line counts the steps run, its total marked an estimate
// ("~"), and its "done" says the steps the summary says.
TEST(Cli, CflProgressCountsTheStepsRun) {
  if (std::system("script --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script` to give the run a terminal";
  std::string deck = mpmx::test::slurp(kExamples + "N3_two_disks_ddmp.toml");
  deck = replaced(replaced(deck, "dt = 0.01", "dt = \"cfl\""), "end = 3.5", "end = 0.5");
  const std::string out = ::testing::TempDir() + "cli_cfl_progress";
  // script(1) gives the run a terminal, where the progress line and its "done" are drawn.
  const std::string cmd = "script -qec '" + std::string(MPMX_BINARY) + " run " + deck_file("cli_cfl.toml", deck) +
                          " -o " + out + " --no-plot --overwrite' /dev/null 2>&1";
  Result r{-1, {}};
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) r.output += buf;
    r.status = pclose(p);
  }
  EXPECT_EQ(r.status, 0) << r.output;
  std::smatch done, summary;
  ASSERT_TRUE(std::regex_search(r.output, done, std::regex(R"(: done, ([0-9]+) steps in)"))) << r.output;
  ASSERT_TRUE(std::regex_search(r.output, summary, std::regex(R"(N3: ([0-9]+) steps in)"))) << r.output;
  EXPECT_EQ(done[1], summary[1]) << r.output;
  EXPECT_EQ(mpmx::test::json_number(mpmx::test::slurp(out + "/run.json"), "steps"), std::stod(summary[1])) << r.output;
  std::filesystem::remove_all(out);
}

// After md --resume the summary's time and rate are this invocation's: it says its steps.
TEST(Cli, ResumedMdSaysTheStepsItRan) {
  const std::string deck = deck_file(
      "cli_md_resume.toml",
      replaced(kSmallMd, "file = \"Cu_mishin1.eam.alloy\"", "file = \"/usr/share/lammps/potentials/Cu_mishin1.eam.alloy\""));
  const std::string out = ::testing::TempDir() + "cli_md_resume";
  std::filesystem::remove_all(out);
  const auto stop = mpmx_cli("md " + deck + " -o " + out + " -q -j 1 --stop-after 100");
  ASSERT_EQ(stop.status, 130) << stop.output;
  const auto r = mpmx_cli("md " + deck + " -o " + out + " -q -j 1 --resume");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("108 atoms, 200 steps (100 of them now, after --resume), "), std::string::npos) << r.output;
  std::filesystem::remove_all(out);
}
