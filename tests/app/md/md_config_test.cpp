// The MD deck reader (app/md/config.hpp): integers range-checked, not wrapped; nan
// refused at read time; the potential file parsed and its elements checked at read time
// (issue 17); [jet] deck errors that name the key, the value and the reason.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "mpmx/app/md/config.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

#include "../../md/md_test_util.hpp"
#include "md_deck_util.hpp"

using namespace mpmx;
using namespace mpmx::md;
using namespace mpmx::app::md;

namespace {

using mpmx::test::kCuMishin;
using mpmx::test::lj_deck;
using mpmx::test::md_config_of;
using mpmx::test::scratch_file;

// What the reader says of a deck, or "(no error)".
std::string error(const std::string& text) {
  try {
    md_config_of(text);
  } catch (const mpmx::InputError& e) {
    return std::string(e.what());
  }
  return std::string("(no error)");
}

}  // namespace

TEST(MdConfigHostile, IntegersAreRangeCheckedNotWrapped) {
  std::string t = lj_deck("5", "10");
  t += "[scan]\nlattice_from = 3.5\nlattice_to = 3.7\npoints = 4294967299\n";
  auto msg = error(t);
  EXPECT_NE(msg.find("key 'scan.points' = 4294967299: out of range: must be an integer from 3 to 100000"),
            std::string::npos)
      << msg;
  t = lj_deck("4294967297, 5, 5", "10");
  msg = error(t);
  EXPECT_NE(msg.find("key 'lattice.cells' = [4294967297, 5, 5]: entry 1 = 4294967297: out of range: must be "
                     "an integer from 1 to 1000"),
            std::string::npos)
      << msg;
  t = lj_deck("5", "10");
  t.replace(t.find("style = \"lj\""), 12, "style = \"sutton_chen\"\na = 3.61\nc = 39.4\nn = 9\nm = 4294967302");
  t.replace(t.find("sigma = 2.3\n"), 12, "");
  msg = error(t);
  EXPECT_NE(msg.find("key 'potential.m' = 4294967302: out of range: must be an integer from 1 to 100"),
            std::string::npos)
      << msg;
  t = lj_deck("5", "10") + "[bar]\ncells_x = 40\ncells_yz = 4\nbins = 4294967396\n";
  msg = error(t);
  EXPECT_NE(msg.find("key 'bar.bins' = 4294967396: out of range: must be an integer from 1 to 100000"),
            std::string::npos)
      << msg;
  t = lj_deck("5", "1e6");
  msg = error(t);
  EXPECT_NE(msg.find("key 'run.steps' = 1000000.0: expected an integer, got a number"), std::string::npos) << msg;
  t = lj_deck("5", "10") + "thermo = 4294967396\n";
  msg = error(t);
  EXPECT_NE(msg.find("key 'run.thermo' = 4294967396: out of range: must be an integer from 1 to 2147483647"),
            std::string::npos)
      << msg;
}

TEST(MdConfigHostile, NanVelocityGradientIsRefusedAtReadTime) {
  std::string t = lj_deck("5", "10") + "velocity_gradient_per_ps = [0, 0, 0, 0, nan, 0, 0, 0, 0]\n";
  try {
    md_config_of(t);
    FAIL() << "nan accepted";
  } catch (const mpmx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'run.velocity_gradient_per_ps' = [0, 0, 0, 0, nan, 0, 0, 0, 0]: "
                                         "entry 5 is nan"),
              std::string::npos)
        << e.what();
  }
}

TEST(MdConfigHostile, PotentialFileIsParsedAndItsElementsCheckedAtReadTime) {
  const std::string empty = scratch_file("Empty2.eam.alloy", "");
  const std::string eam = "[potential]\nstyle = \"eam\"\nfile = \"FILE\"\nelements = [ELEMENTS]\n"
                          "[lattice]\nconstant = 3.615\ncells = [3]\n[run]\ndt = 0.001\nsteps = 10\n";
  auto deck = [&](const std::string& file, const std::string& elements) {
    std::string t = eam;
    t.replace(t.find("FILE"), 4, file);
    t.replace(t.find("ELEMENTS"), 8, elements);
    return t;
  };
  auto msg = error(deck(empty, "\"Cu\""));
  EXPECT_NE(msg.find("key 'potential.file'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the EAM potential file is empty"), std::string::npos) << msg;
  msg = error(deck(kCuMishin, "\"Cu\", \"Zr\""));
  EXPECT_NE(msg.find("key 'potential.elements' = [\"Cu\", \"Zr\"]: element 'Zr' is not in"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("(it has: Cu)"), std::string::npos) << msg;
  EXPECT_EQ(error(deck(kCuMishin, "\"Cu\"")), "(no error)");
}

TEST(JetDeck, ErrorsNameKeyValueAndReason) {
  const std::string head = R"(
[potential]
file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.615
cells = [1, 1, 1]
[run]
dt = 0.001
)";
  auto error_of = [&](const std::string& run_extra, const std::string& jet) {
    auto deck = io::Deck::from_string(head + run_extra + "[jet]\n" + jet, "jet.toml");
    try {
      (void)read_md_config(deck);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string good = "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\nbins = [8, 4]\n"
                           "duration_ps = 30.0\nrecord_every_ps = 1.0\n";
  EXPECT_EQ(error_of("", good + "scale = 0.04\n"), "");
  auto has = [](const std::string& msg, const std::string& part) {
    return msg.find(part) != std::string::npos;
  };
  EXPECT_TRUE(has(error_of("steps = 100\n", good), "run.steps")) << error_of("steps = 100\n", good);
  const std::string neg = error_of("", good + "scale = -1.0\n");
  EXPECT_TRUE(has(neg, "jet.scale") && has(neg, "-1") && has(neg, "(0, 10]")) << neg;
  const std::string nan = error_of("", good + "scale = nan\n");
  EXPECT_TRUE(has(nan, "jet.scale")) << nan;
  const std::string deep = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 140.0\n"
                                        "bins = [8, 4]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(deep, "jet.notch_depth_nm") && has(deep, "shallower")) << deep;
  const std::string bins = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                        "bins = [8]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(bins, "jet.bins")) << bins;
  const std::string every = error_of("", good + "scale = 0.0001\n");
  EXPECT_TRUE(has(every, "jet.record_every_ps")) << every;
  const std::string big = error_of("", "cells = [400, 200, 1000000]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                       "bins = [8, 4]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(big, "jet.cells") && has(big, "1000000")) << big;
  const std::string many = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                        "bins = [100000, 100000]\nduration_ps = 30.0\nrecord_every_ps = 1.0\n");
  EXPECT_TRUE(has(many, "jet.bins") && has(many, "10^7")) << many;
  // Issue 31: a duration of 100.5 steps was run as 100 without a word.
  const std::string half = error_of("", "cells = [400, 200, 3]\npiston_cells = 40\nnotch_depth_nm = 36.0\n"
                                        "bins = [8, 4]\nduration_ps = 1.005\nrecord_every_ps = 1.005\nscale = 0.1\n");
  EXPECT_TRUE(has(half, "jet.duration_ps") && has(half, "100.5") && has(half, "not a whole number")) << half;
}

// Inputs that cannot be an atom's crystal (issue 45): refused by the reader with the key,
// the value and the reason, so that `check` and the run both stop with exit 2.
TEST(MdConfigPhysical, AtomsCloserThanABondAreRefused) {
  std::string t = lj_deck("3", "10");
  t.replace(t.find("constant = 3.615"), 16, "constant = 0.1");
  auto msg = error(t);
  EXPECT_NE(msg.find("key 'lattice.constant' = 0.1: fcc nearest neighbours would be 0.07071 A apart (constant / "
                     "sqrt 2), closer than any bond (1 A)"),
            std::string::npos)
      << msg;
  // The bound itself: nearest neighbours exactly 1 A apart are a crystal.
  t = lj_deck("3", "10");
  t.replace(t.find("constant = 3.615"), 16, "constant = 1.4143");
  EXPECT_EQ(error(t), "(no error)");
  t = lj_deck("3", "10") + "[scan]\nlattice_from = 1.2\nlattice_to = 3.7\n";
  msg = error(t);
  EXPECT_NE(msg.find("key 'scan.lattice_from' = 1.2: fcc nearest neighbours would be 0.8485 A apart"),
            std::string::npos)
      << msg;
}

TEST(MdConfigPhysical, MassesOutsideAnAtomsAreRefused) {
  for (const std::string mass : {"1e-300", "0.4", "1001.5"}) {
    std::string t = lj_deck("3", "10");
    t.replace(t.find("mass = 63.5"), 11, "mass = " + mass);
    const auto msg = error(t);
    EXPECT_NE(msg.find("key 'potential.mass' = " + mass + ": an atom's mass lies in [0.5, 1000] amu"),
              std::string::npos)
        << msg;
  }
}

// Step counts whose sum the run's counter cannot hold are refused, not wrapped (issue 45).
TEST(MdConfigHostile, StepSumsPastAnInt64AreRefused) {
  const std::string t = lj_deck("3", "1000") + "[thermal]\nrelax_steps = 9223372036854775000\n";
  const std::string msg = error(t);
  EXPECT_NE(msg.find("key 'thermal.relax_steps' = 9223372036854775000: plus run.steps is more steps than a run "
                     "can count"),
            std::string::npos)
      << msg;
  EXPECT_EQ(error(lj_deck("3", "1000") + "[thermal]\nrelax_steps = 9223372036854774807\n"), "(no error)");
}

// [lattice]'s type, orient and c_over_a (M6): an oriented bcc box read; a bad set refused
// naming the key, the value and the reason; c_over_a only for hcp; a [bar] of any, a [rod] of one element.
TEST(MdConfigLattice, OrientedCrystalsReadAndBadSetsRefused) {
  auto deck = [](const std::string& lattice) {
    std::string t = lj_deck("3", "10");
    t.replace(t.find("[lattice]\n"), 10, "[lattice]\n" + lattice + "\n");
    return t;
  };
  MdConfig c = md_config_of(deck("type = \"bcc\"\norient = [[1, 1, 1], [-1, 1, 0], [-1, -1, 2]]"));
  EXPECT_EQ(c.lattice.style, mpmx::particles::LatticeStyle::bcc);
  EXPECT_EQ(c.lattice.orient[2][2], 2);
  EXPECT_EQ(c.lattice.constant, c.lattice_constant);
  std::string msg = error(deck("type = \"bcc\"\norient = [[1, 1, 0], [1, -1, 0], [0, 0, 1]]"));
  EXPECT_NE(msg.find("key 'lattice.orient' = [[1, 1, 0], [1, -1, 0], [0, 0, 1]]: [1,1,0] x [1,-1,0] is opposite to "
                     "[0,0,1]: the set is left-handed"),
            std::string::npos)
      << msg;
  msg = error(deck("type = \"fcc\"\norient = [[1, 1, 0], [0, 1, 0]]"));
  EXPECT_NE(msg.find("key 'lattice.orient'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected three directions"), std::string::npos) << msg;
  msg = error(deck("type = \"hcp\"\norient = [[1, 1, 0], [-1, 1, 0], [0, 0, 1]]"));
  EXPECT_NE(msg.find("off the hcp cell's axes"), std::string::npos) << msg;
  msg = error(deck("type = \"bcc\"\nc_over_a = 1.6"));
  EXPECT_NE(msg.find("key 'lattice.c_over_a' = 1.6: applies to an hcp lattice only"), std::string::npos) << msg;
  c = md_config_of(deck("type = \"hcp\"\nc_over_a = 1.593"));
  EXPECT_EQ(c.lattice.c_over_a, 1.593);
  msg = error(deck("type = \"b2\""));  // lj: one element
  EXPECT_NE(msg.find("key 'lattice.type' = \"b2\": b2 puts potential.elements[0] on the cube corners"),
            std::string::npos)
      << msg;
  c = md_config_of(deck("type = \"bcc\"") + "[bar]\ncells_x = 10\ncells_yz = 3\n");
  EXPECT_EQ(c.bar_config.lattice.style, mpmx::particles::LatticeStyle::bcc);
  c = md_config_of(deck("type = \"bcc\"") +
                   "[rod]\ntarget_cells = [4, 4, 4]\nflyer_cells = 2\nflyer_velocity = 5.0\nrescale_every = 0\n");
  EXPECT_EQ(c.rod_config.lattice.style, mpmx::particles::LatticeStyle::bcc);
  msg = error(deck("type = \"b2\"") +
              "[rod]\ntarget_cells = [4, 4, 4]\nflyer_cells = 2\nflyer_velocity = 5.0\nrescale_every = 0\n");
  EXPECT_NE(msg.find("key 'lattice.type' = \"b2\": a [jet] or [rod] sample is of one element"), std::string::npos)
      << msg;
}

// A [jet] and a [rod] of an oriented lattice count its tiles: their checks state the
// tiles' lengths, the notch stays in nm against the block's length in Angstrom, and a
// rod's track between two of the target's planes is refused naming where they lie.
TEST(MdConfigLattice, JetAndRodCountTilesOfTheOrientedLattice) {
  const std::string lattice = "[lattice]\ntype = \"bcc\"\nconstant = 2.8553\norient = [[1, 1, 1], [-1, 1, 0], "
                              "[-1, -1, 2]]\ncells = [1, 1, 1]\n";
  const std::string head = "[potential]\nfile = \"" + mpmx::test::kLammpsPotentials +
                           "Fe_mm.eam.fs\"\nelements = [\"Fe\"]\n" + lattice + "[run]\ndt = 0.001\n";
  const std::string jet = "[jet]\ncells = [24, 6, 2]\npiston_cells = 3\nbins = [8, 2]\nduration_ps = 0.04\n"
                          "record_every_ps = 0.01\nscale = 1.0\n";
  MdConfig c = md_config_of(head + jet + "notch_depth_nm = 0.5\n");
  EXPECT_EQ(c.jet_config.lattice.style, mpmx::particles::LatticeStyle::bcc);
  EXPECT_EQ(c.jet_config.lattice.orient[0][2], 1);
  // 21 block tiles of sqrt(3)/2 a = 2.4728 A: 51.928 A; a 6 nm notch is deeper.
  std::string msg = error(head + jet + "notch_depth_nm = 6.0\n");
  EXPECT_NE(msg.find("key 'jet.notch_depth_nm' = 6: at scale 1 the notch (60 A) is not shallower than the block "
                     "(51.928009"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("21 tiles of 2.47276 x 4.038 x 6.99403 A)"), std::string::npos) << msg;
  msg = error(head + "[jet]\ncells = [24, 6, 2]\npiston_cells = 24\nbins = [8, 2]\nduration_ps = 0.04\n"
                     "record_every_ps = 0.01\nnotch_depth_nm = 0.5\n");
  EXPECT_NE(msg.find("key 'jet.piston_cells' = 24: at scale 1 the piston is 24 of 24 tiles of 2.47276"),
            std::string::npos)
      << msg;
  // The rod's target planes along [111]: three per tile, at 0, 0.824 and 1.649 A.
  const std::string rod = "[rod]\ntarget_cells = [10, 2, 1]\nflyer_cells = 2\nflyer_velocity = 5.0\n"
                          "rescale_every = 0\n[[track]]\nname = \"r\"\nx = [";
  c = md_config_of(head + "steps = 10\n" + rod + "5.5, 6.0]\n");  // the face at 4.9455 A, a plane at 5.7698
  EXPECT_EQ(c.rod_config.lattice.orient[1][0], -1);
  msg = error(head + "steps = 10\n" + rod + "5.0, 5.7]\n");
  EXPECT_NE(msg.find("track \"r\": x = [5, 5.7) A holds no atomic plane of the target (planes at 0, 0.824254, "
                     "1.64851 A in each tile of 2.47276 A from the impact face at"),
            std::string::npos)
      << msg;
}

// ------------------------------------------------ ensembles: one error per mistake

namespace {

// The errors a deck gets, one a line (none: empty).
std::vector<std::string> error_lines(const std::string& text) {
  std::vector<std::string> lines;
  const std::string all = error(text);
  if (all == "(no error)") return lines;
  std::size_t at = 0;
  for (std::size_t nl; (nl = all.find('\n', at)) != std::string::npos; at = nl + 1)
    lines.push_back(all.substr(at, nl - at));
  lines.push_back(all.substr(at));
  return lines;
}

const std::string kWarmBox = lj_deck("3", "100") + "[thermal]\ntemperature = 300.0\n";

// The warm box's [run] with `keys` added (before any table the caller appends).
std::string warm_run(const std::string& keys) {
  const std::size_t thermal = kWarmBox.find("[thermal]");
  return kWarmBox.substr(0, thermal) + keys + kWarmBox.substr(thermal);
}

}  // namespace

// A thermostat's target or the barostat's kT at 0 K would stop the run (its chains'
// masses are kT over a frequency): the reader refuses it, so `check` does too.
TEST(MdConfigEnsemble, EveryEnsembleAtZeroKelvinIsRefused) {
  const std::string cold = lj_deck("3", "100");  // thermal.temperature 0 by default
  for (const std::string e : {"nvt", "npt", "nph", "nphug"}) {
    const auto lines = error_lines(cold + "ensemble = \"" + e + "\"\n" + (e == "nphug" ? "pressure_gpa = 1.0\n" : ""));
    ASSERT_EQ(lines.size(), 1u) << e;
    EXPECT_NE(lines[0].find("key 'run.ensemble' = \"" + e + "\": needs thermal.temperature > 0, not 0 K: "),
              std::string::npos)
        << lines[0];
    EXPECT_NE(lines[0].find(e == "nph" ? "the barostat's kT is the box's temperature at the start"
                                       : "it is the thermostat's target"),
              std::string::npos)
        << lines[0];
  }
  EXPECT_EQ(error(cold + "ensemble = \"nve\"\n"), "(no error)");
  EXPECT_EQ(error(warm_run("ensemble = \"nph\"\n")), "(no error)");
}

// A period of fewer than 10 steps is not integrated: refused, naming the steps.
TEST(MdConfigEnsemble, PeriodsShorterThanTenStepsAreRefused) {
  auto lines = error_lines(warm_run("ensemble = \"npt\"\nt_damp_ps = 0.0005\np_damp_ps = 0.02\n"));
  ASSERT_EQ(lines.size(), 1u) << error(warm_run("ensemble = \"npt\"\nt_damp_ps = 0.0005\np_damp_ps = 0.02\n"));
  EXPECT_NE(lines[0].find("key 'run.t_damp_ps' = 0.0005: is 0.5 steps of run.dt = 0.001 ps: a Nose-Hoover period "
                          "spans at least 10 (LAMMPS advises 100)"),
            std::string::npos)
      << lines[0];
  lines = error_lines(warm_run("ensemble = \"nph\"\np_damp_ps = 0.009\n"));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("key 'run.p_damp_ps' = 0.009: is 9 steps of run.dt = 0.001 ps"), std::string::npos)
      << lines[0];
  lines = error_lines(warm_run("ensemble = \"nvt\"\nt_damp_ps = -1.0\n"));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("key 'run.t_damp_ps' = -1: must be positive"), std::string::npos) << lines[0];
  EXPECT_EQ(error(warm_run("ensemble = \"npt\"\nt_damp_ps = 0.01\np_damp_ps = 0.01\n")), "(no error)");
}

// A misspelt or mistyped ensemble is one error: its keys are neither refused one by one
// for the fallback nve nor called unknown.
TEST(MdConfigEnsemble, AMisspeltEnsembleIsOneError) {
  const std::string keys =
      "t_damp_ps = 0.1\np_damp_ps = 1.0\npressure_gpa = 1.0\nshock_axis = \"x\"\nbarostat = \"iso\"\n";
  auto lines = error_lines(warm_run("ensemble = \"nphugg\"\n" + keys));
  ASSERT_EQ(lines.size(), 1u) << error(warm_run("ensemble = \"nphugg\"\n" + keys));
  EXPECT_NE(lines[0].find("key 'run.ensemble' = \"nphugg\": not one of nve, nvt, npt, nph, nphug"), std::string::npos)
      << lines[0];
  lines = error_lines(warm_run("ensemble = 3\n" + keys));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("key 'run.ensemble' = 3: expected a string"), std::string::npos) << lines[0];
  // A key the ensemble has no use for: its one error, not also "unknown key".
  lines = error_lines(warm_run("ensemble = \"nphug\"\npressure_gpa = 1.0\nbarostat = \"iso\"\n"));
  ASSERT_EQ(lines.size(), 1u) << error(warm_run("ensemble = \"nphug\"\npressure_gpa = 1.0\nbarostat = \"iso\"\n"));
  EXPECT_NE(lines[0].find("key 'run.barostat' = \"iso\": has no use with ensemble = \"nphug\""), std::string::npos)
      << lines[0];
  lines = error_lines(warm_run("shock_axis = \"z\"\nt_damp_ps = 0.1\n"));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("key 'run.t_damp_ps' = 0.1: has no use with ensemble = \"nve\""), std::string::npos)
      << lines[0];
  EXPECT_NE(lines[1].find("key 'run.shock_axis' = \"z\": has no use with ensemble = \"nve\""), std::string::npos)
      << lines[1];
}

// A [bar], [jet] or [rod] run is NVE: an ensemble there (and the keys that would tune
// it) is one error naming the sample, not a run that writes its nve twin's bytes.
TEST(MdConfigEnsemble, SamplesRefuseAnEnsemble) {
  const std::string bar = "[bar]\ncells_x = 10\ncells_yz = 3\n";
  const std::string rod = "[rod]\ntarget_cells = [4, 4, 4]\nflyer_cells = 2\nflyer_velocity = 5.0\n";
  const std::string jet = "[jet]\ncells = [40, 20, 3]\npiston_cells = 4\nnotch_depth_nm = 1.0\nbins = [8, 4]\n"
                          "duration_ps = 0.1\nrecord_every_ps = 0.05\n";
  const std::vector<std::pair<std::string, std::string>> samples{{"bar", bar}, {"rod", rod}, {"jet", jet}};
  for (const auto& [name, table] : samples) {
    for (const std::string e : {"nvt", "npt", "nph", "nphug"}) {
      std::string text = warm_run("ensemble = \"" + e + "\"\npressure_gpa = 1.0\n") + table;
      if (name == "jet") text.replace(text.find("steps = 100\n"), 12, "");
      const auto lines = error_lines(text);
      ASSERT_EQ(lines.size(), 1u) << error(text);
      EXPECT_NE(lines[0].find("key 'run.ensemble' = \"" + e + "\": a [" + name + "] run is NVE ("), std::string::npos)
          << lines[0];
      EXPECT_NE(lines[0].find("); ensembles apply to periodic boxes"), std::string::npos) << lines[0];
    }
    std::string text = warm_run("ensemble = \"nve\"\nt_damp_ps = 0.1\n") + table;
    if (name == "jet") text.replace(text.find("steps = 100\n"), 12, "");
    const auto lines = error_lines(text);
    ASSERT_EQ(lines.size(), 1u) << error(text);
    EXPECT_NE(lines[0].find("key 'run.t_damp_ps' = 0.1: has no use: a [" + name + "] run is NVE"), std::string::npos)
        << lines[0];
    text = warm_run("ensemble = \"nve\"\n") + table;
    if (name == "jet") text.replace(text.find("steps = 100\n"), 12, "");
    EXPECT_EQ(error(text), "(no error)") << name;
  }
}

// The periodic box's keys in a sample's deck (issue 54: nothing accepted and ignored): a
// [bar], [jet] or [rod] is not deformed as a whole, relaxed by relax_steps or strained by
// strain_x, and a [bar] writes no dump frames: each such key is one error naming why.
TEST(MdConfigSample, ThePeriodicBoxsKeysAreRefused) {
  const std::string bar = "[bar]\ncells_x = 10\ncells_yz = 3\n";
  const std::string rod = "[rod]\ntarget_cells = [4, 4, 4]\nflyer_cells = 2\nflyer_velocity = 5.0\n";
  const std::string jet = "[jet]\ncells = [40, 20, 3]\npiston_cells = 4\nnotch_depth_nm = 1.0\nbins = [8, 4]\n"
                          "duration_ps = 0.1\nrecord_every_ps = 0.05\n";
  const std::vector<std::pair<std::string, std::string>> samples{{"bar", bar}, {"rod", rod}, {"jet", jet}};
  const std::vector<std::pair<std::string, std::string>> keys{{"strain_rate_per_s = 1e9\n", "run.strain_rate_per_s"},
                                                              {"streaming_start = true\n", "run.streaming_start"},
                                                              {"deformation = \"affine\"\n", "run.deformation"}};
  for (const auto& sample : samples) {
    const std::string& name = sample.first;  // named, not bound: clang 14 captures no binding
    const std::string& table = sample.second;
    auto text_with = [&](const std::string& run_keys) {
      std::string text = warm_run(run_keys) + table;
      if (name == "jet") text.replace(text.find("steps = 100\n"), 12, "");
      return text;
    };
    for (const auto& [line, key] : keys) {
      const auto lines = error_lines(text_with(line));
      ASSERT_EQ(lines.size(), 1u) << name << ": " << error(text_with(line));
      EXPECT_NE(lines[0].find("key '" + key + "'"), std::string::npos) << lines[0];
      EXPECT_NE(lines[0].find("has no use in a [" + name + "] run"), std::string::npos) << lines[0];
    }
    EXPECT_EQ(error(text_with("")), "(no error)") << name;
  }
  std::string text = warm_run("dump_every = 100\n") + bar;
  const auto lines = error_lines(text);
  ASSERT_EQ(lines.size(), 1u) << error(text);
  EXPECT_NE(lines[0].find("key 'run.dump_every' = 100: has no use in a [bar] run"), std::string::npos) << lines[0];
}
