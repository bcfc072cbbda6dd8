// ctest-cost: 1
// `check`'s unit-slip warnings cover every velocity a deck holds (bodies, their spin,
// [initial.velocity], pistons, velocity faces) and every law's density, name bodies as
// run.json does (from 0, with their names escaped), and go with a numeric dt's CFL error,
// which a speed typed in m/s for km/s is the usual cause of.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_util.hpp"
#include "mpm_deck_test_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/unit_slips.hpp"

namespace {

using mpmx::test::replace;

const char* kPiston1d = R"(
[case]
id = "slips_1d"
units = "nm_ps_GPa"
[grid]
upper = 10.0
cells = 100
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
youngs_modulus = 233.0
density = 8.9
[boundary]
left = { type = "piston", velocity = 0.5 }
[time]
dt = 1e-4
end = 1e-3
)";

// A piston carries the grid, and the face across from it must be free: a velocity face
// goes on the other axis.
const char* kPiston2d = R"(
[case]
id = "slips_2d_piston"
units = "nm_ps_GPa"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [10.0, 0.1]
cells = [100, 1]
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
youngs_modulus = 233.0
density = 8.9
[boundary]
x_lower = { type = "piston", velocity = 0.5 }
y_lower = { type = "roller" }
y_upper = { type = "velocity", value = [0.0, 0.0] }
[time]
dt = 1e-4
end = 1e-3
)";

const char* kFlyer2d = R"(
[case]
id = "slips_2d"
units = "nm_ps_GPa"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [12.0, 0.1]
cells = [120, 1]
[particles]
per_cell = [2, 1]
[[body]]
name = "flyer"
shape = "box"
lower = [0.0, 0.0]
upper = [3.0, 0.1]
velocity = [1.0, 0.0]
[[body]]
name = "target"
shape = "box"
lower = [3.0, 0.0]
upper = [9.0, 0.1]
[scheme]
name = "cpdi"
[material]
model = "linear_elastic"
youngs_modulus = 70.0
density = 2.7
[[gauge]]
name = "rear"
type = "free_surface"
body = "target"
face = "x_upper"
[time]
dt = 1e-3
end = 0.1
)";

std::string all(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

std::string deck_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(UnitSlips, APistonsAndAVelocityFacesSpeedsAreJudged) {
  // 1-D: a piston on the left, or a velocity face on the right.
  const std::string velocity1d = replace(kPiston1d, "left = { type = \"piston\", velocity = 0.5 }",
                                         "right = { type = \"velocity\", value = 0.0 }");
  for (const std::string& deck : {std::string(kPiston1d), velocity1d})
    EXPECT_EQ(all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(deck, "p.toml"))), "") << deck;
  // 500 m/s typed for 0.5 km/s; its travel kept on the grid by a shorter run.
  const auto shorter = [](const std::string& deck) {
    return replace(deck, "dt = 1e-4\nend = 1e-3", "dt = 1e-7\nend = 1e-6");
  };
  const std::string piston = all(mpmx::app::unit_slips(
      mpmx::app::read_mpm_deck_text(shorter(replace(kPiston1d, "velocity = 0.5 }", "velocity = 500.0 }")), "p.toml")));
  EXPECT_HAS(piston,
             "boundary.left.velocity = 500 in nm_ps_GPa is 5e+05 m/s, far above the range for a speed of a solid "
             "(0 to 50000 m/s): m/s typed for km/s? (0.5 would be 500 m/s)");
  EXPECT_EQ(mpmx::test::count(piston, "\n"), 1u) << piston;
  const std::string face = all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(
      shorter(replace(velocity1d, "value = 0.0 }", "value = 0.0, amplitude = 2000.0, omega = 1.0 }")), "v.toml")));
  EXPECT_HAS(face, "boundary.right.amplitude = 2000 in nm_ps_GPa is 2e+06 m/s");
  EXPECT_EQ(mpmx::test::count(face, "\n"), 1u) << face;
  // 2-D: both in one deck, each named by its face.
  EXPECT_EQ(all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(kPiston2d, "p2.toml"))), "");
  const std::string both = all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(
      shorter(replace(replace(kPiston2d, "velocity = 0.5 }", "velocity = 500.0 }"), "value = [0.0, 0.0] }",
                      "value = [0.0, 0.0], amplitude = [2000.0, 0.0], omega = 1.0 }")),
      "p2.toml")));
  EXPECT_HAS(both, "boundary.x_lower.velocity = 500 in nm_ps_GPa is 5e+05 m/s");
  EXPECT_HAS(both, "boundary.y_upper.amplitude = 2000 in nm_ps_GPa is 2e+06 m/s");
  EXPECT_EQ(mpmx::test::count(both, "\n"), 2u) << both;
}

TEST(UnitSlips, BodiesAreNamedFromZeroAsRunJsonNumbersThem) {
  const auto c = mpmx::app::read_mpm_deck_text(
      replace(replace(kFlyer2d, "velocity = [1.0, 0.0]", "velocity = [1000.0, 0.0]"), "dt = 1e-3", "dt = 1e-5"),
      "f.toml");
  const std::string w = all(mpmx::app::unit_slips(c));
  EXPECT_HAS(w, "[[body]] 0 (\"flyer\") velocity = 1000 in nm_ps_GPa is 1e+06 m/s");
  EXPECT_HAS(w, ": m/s typed for km/s? (1 would be 1e+03 m/s)");
}

// A numeric dt too long for the slipped speed: the error itself gives the hint (check
// stops there, before its warnings).
TEST(UnitSlips, ANumericDtsCflErrorCarriesTheHint) {
  const auto r = mpmx::test::run_cli(
      "check " + deck_file("slip_flyer.toml", replace(kFlyer2d, "velocity = [1.0, 0.0]", "velocity = [1000.0, 0.0]")));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_HAS(r.output, "key 'time.dt' = 0.001: exceeds the CFL limit");
  EXPECT_HAS(r.output, "; [[body]] 0 (\"flyer\") velocity = 1000 in nm_ps_GPa is 1e+06 m/s");
  EXPECT_HAS(r.output, "m/s typed for km/s? (1 would be 1e+03 m/s)");
}

TEST(UnitSlips, AGassDensityAndSoundSpeedAreJudged) {
  const std::string gas = R"(
[case]
id = "gas"
units = "nm_ps_GPa"
[grid]
upper = 1.0
cells = 10
[scheme]
name = "mpm"
[material]
model = "ideal_gas_isothermal"
density = 8900.0
sound_speed = 0.3
[time]
dt = 1e-3
end = 1e-2
)";
  const std::string w = all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(gas, "g.toml")));
  EXPECT_HAS(w, "[material] density = 8900 in nm_ps_GPa is 8.9e+06 kg/m^3, far above the range for a density of a "
                "gas (0 to 30000 kg/m^3): kg/m^3 typed for g/cm^3?");
  EXPECT_EQ(mpmx::test::count(w, "\n"), 1u) << w;
  const std::string fast = all(mpmx::app::unit_slips(mpmx::app::read_mpm_deck_text(
      replace(replace(replace(gas, "density = 8900.0", "density = 0.0012"), "sound_speed = 0.3", "sound_speed = 300.0"),
              "dt = 1e-3\nend = 1e-2", "dt = 1e-5\nend = 1e-4"),
      "g.toml")));
  EXPECT_HAS(fast, "[material] sound_speed = 300 in nm_ps_GPa is 3e+05 m/s");
}

// A body's name is printed with its control characters escaped (check's gauge line, the
// warnings).
TEST(UnitSlips, ABodysNameIsPrintedEscaped) {
  const std::string text = replace(replace(kFlyer2d, "name = \"target\"", "name = \"tar\\u001bget\""),
                                   "body = \"target\"", "body = \"tar\\u001bget\"");
  const auto r = mpmx::test::run_cli("check " + deck_file("escaped_body.toml", text));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_HAS(r.output, "the outermost points of tar\\x1bget's x_upper face");
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  // A body's own slip names it escaped, from 0.
  const auto c = mpmx::app::read_mpm_deck_text(
      replace(replace(text, "upper = [9.0, 0.1]", "upper = [9.0, 0.1]\nvelocity = [1000.0, 0.0]"), "dt = 1e-3",
              "dt = 1e-5"),
      "e.toml");
  EXPECT_HAS(all(mpmx::app::unit_slips(c)), "[[body]] 1 (\"tar\\x1bget\") velocity = 1000");
}
