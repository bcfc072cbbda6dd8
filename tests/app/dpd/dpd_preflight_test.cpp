// What a DPD run checks before its work, and `mpmx dpd --check` with it (app/dpd/
// preflight.hpp): a rigid, track or continuum region holding no particle, rigid groups
// that overlap, lengths that overflow, counts past an int: refused by both, alike.
#include <gtest/gtest.h>

#include <string>

#include "cli_util.hpp"
#include "md/md_test_util.hpp"
#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/dpd/preflight.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

namespace {

using namespace mpmx;

const std::string kBase = R"([case]
id = "DP"
[potential]
style = "morse"
d0 = 0.5
alpha = 1.0
r0 = 3.0
cutoff = 8.0
[[block]]
lattice = "fcc"
constant = 4.0
cells = [6, 4, 4]
mass = 100.0
[box]
boundary = ["f", "f", "f"]
[dpd]
ensemble = "dpd"
integrator = "velocity_verlet"
gamma = 1.0
temperature = 100.0
[run]
dt = 0.005
steps = 10
thermo = 5
)";

std::string refusal(const std::string& text) {
  try {
    io::Deck d = io::Deck::from_string(text, "dp.toml");
    const auto c = app::dpd::read_dpd_config(d);
    app::dpd::preflight_dpd(c, false);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(DpdPreflight, RegionsHoldingNoParticleAreRefused) {
  EXPECT_EQ(refusal(kBase), "");
  EXPECT_HAS(refusal(kBase + "[[rigid]]\nname = \"g\"\nx = [500.0, 600.0]\n"),
             "rigid group \"g\": its region holds no particle");
  EXPECT_HAS(refusal(kBase + "[[track]]\nname = \"a\"\nx = [500.0, 600.0]\n"),
             "track \"a\": no mobile particle has x in [500, 600) A");
  EXPECT_HAS(refusal(kBase + "[grid]\ncell = 4.0\n[continuum]\nx = [500.0, 600.0]\nlattice_constant = 4.0\n"),
             "continuum.x = [500, 600]: no mobile particle lies there");
  // A track over the rigid grip only: its particles are not mobile.
  EXPECT_HAS(refusal(kBase + "[[rigid]]\nname = \"g\"\nx = [-1.0, 3.0]\n[[track]]\nname = \"a\"\nx = [-1.0, 1.0]\n"),
             "track \"a\": no mobile particle");
}

TEST(DpdPreflight, OverlappingRigidGroupsAreRefused) {
  EXPECT_HAS(refusal(kBase + "[[rigid]]\nname = \"g\"\nx = [0.0, 10.0]\n[[rigid]]\nname = \"h\"\nx = [5.0, 12.0]\n"),
             "rigid group \"h\": its region overlaps rigid group \"g\" (64 particles lie in both)");
  EXPECT_EQ(refusal(kBase + "[[rigid]]\nname = \"g\"\nx = [0.0, 5.0]\n[[rigid]]\nname = \"h\"\nx = [5.0, 12.0]\n"), "");
  // A region over a rigid block's particles.
  EXPECT_HAS(refusal(kBase + "[[block]]\nlattice = \"fcc\"\nconstant = 4.0\ncells = [2, 4, 4]\norigin = [30.0, 0.0, 0.0]\n"
                             "mass = 100.0\ngroup = \"flyer\"\n[[rigid]]\nname = \"g\"\nx = [28.0, 100.0]\n"),
             "rigid group \"g\": its region overlaps rigid group \"flyer\"");
}

TEST(DpdPreflight, LengthsAndCountsAreBounded) {
  std::string huge = kBase;
  huge.replace(huge.find("constant = 4.0"), 14, "constant = 1e308");
  EXPECT_HAS(refusal(huge), "key 'block[0].constant'");
  EXPECT_HAS(refusal(huge), "must lie in (0, 1000] Angstrom");
  std::string thermo = kBase;
  thermo.replace(thermo.find("thermo = 5"), 10, "thermo = 4294967297");
  EXPECT_HAS(refusal(thermo), "key 'run.thermo' = 4294967297: out of range");
  EXPECT_HAS(refusal(kBase + "[analysis]\nonset_direction = 4294967295\n"),
             "key 'analysis.onset_direction' = 4294967295: out of range");
  EXPECT_HAS(refusal(kBase + "[profile]\nbins = 4294967298\nevery = 5\n"), "key 'profile.bins' = 4294967298: out of range");
}

// `mpmx dpd --check` refuses what the run refuses, with the same words, and nothing is written.
TEST(DpdPreflight, CheckAndRunAgree) {
  const auto bad = test::scratch_file("dpd_preflight_rigid.toml", kBase + "[[rigid]]\nname = \"g\"\nx = [500.0, 600.0]\n");
  const auto check = test::run_cli("dpd " + bad.string() + " --check");
  EXPECT_EQ(check.status, 2) << check.output;
  EXPECT_HAS(check.output, "rigid group \"g\": its region holds no particle");
  const auto out = test::scratch_root() / "dpd_preflight_out";
  const auto run = test::run_cli("dpd " + bad.string() + " --quiet --no-plot --threads 1 --out " + out.string());
  EXPECT_EQ(run.status, 2) << run.output;
  EXPECT_HAS(run.output, "rigid group \"g\": its region holds no particle");
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
