// ctest-cost: 1
// The piston's and the gauges' deck keys: a good deck reads into the config, and each
// bad one is refused naming the key, the value and the reason (a program of its own, so
// that it builds without the whole unit program).
#include <gtest/gtest.h>

#include <string>

#include "cli_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/describe.hpp"
#include "mpm_deck_test_util.hpp"
#include "mpmx/core/error.hpp"

namespace {

const char* kPiston1d = R"(
[case]
id = "T"
[grid]
upper = 10.0
cells = 100
[particles]
per_cell = 2
[scheme]
name = "ddmp"
[material]
model = "linear_elastic"
youngs_modulus = 233.0
density = 8.9
[boundary]
left = { type = "piston", velocity = 0.5 }
[[gauge]]
at = 5.0
[time]
dt = 1e-2
end = 1.0
)";

const char* kPlate2d = R"(
[case]
id = "T2"
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
name = "mid"
at = [4.5, 0.05]
[[gauge]]
name = "rear"
type = "free_surface"
body = "target"
face = "x_upper"
every = 10
[time]
dt = 1e-3
end = 0.1
)";

}  // namespace

using mpmx::test::replace;
constexpr auto deck_error = mpmx::test::mpm_deck_error;

TEST(PistonDeck, ConstantSpeedReads) {
  const auto c = mpmx::app::read_mpm_deck_text(kPiston1d);
  const auto& left = c.boundary.left();
  EXPECT_EQ(left.type, mpmx::mpm::BoundarySide::Type::piston);
  EXPECT_FALSE(left.prescribed());
  EXPECT_EQ(left.piston.speed(0.3), 0.5);
  EXPECT_DOUBLE_EQ(left.piston.travel(0.8), 0.4);
}

TEST(PistonDeck, VelocityHistoryIsATableJoinedByLines) {
  const auto c = mpmx::app::read_mpm_deck_text(
      replace(kPiston1d, "velocity = 0.5 }", "times = [0.0, 0.2, 0.6], velocity = [0.0, 1.0, 1.0] }"));
  const auto& p = c.boundary.left().piston;
  EXPECT_DOUBLE_EQ(p.speed(0.1), 0.5);
  EXPECT_DOUBLE_EQ(p.speed(0.9), 1.0);                   // held past the table's end
  EXPECT_DOUBLE_EQ(p.travel(0.2), 0.1);                  // the ramp's area
  EXPECT_DOUBLE_EQ(p.travel(0.8), 0.1 + 0.6);            // then 1.0 for 0.6
  EXPECT_DOUBLE_EQ(p.travel(0.1), 0.5 * 0.1 * 0.5);      // half-way up the ramp
}

TEST(PistonDeck, TimesNotIncreasingAreRefused) {
  const std::string e = deck_error(
      replace(kPiston1d, "velocity = 0.5 }", "times = [0.0, 0.3, 0.3], velocity = [0.0, 1.0, 1.0] }"));
  EXPECT_HAS(e, "boundary.left.times");
  EXPECT_HAS(e, "must increase: times[2] = 0.3 does not follow times[1] = 0.3");
}

TEST(PistonDeck, OneSpeedPerTime) {
  const std::string e =
      deck_error(replace(kPiston1d, "velocity = 0.5 }", "times = [0.0, 0.3], velocity = [0.0, 1.0, 1.0] }"));
  EXPECT_HAS(e, "boundary.left.velocity");
  EXPECT_HAS(e, "one speed per entry of times (2 times, 3 speeds)");
}

TEST(PistonDeck, PistonPastTheGridIsRefused) {
  const std::string e = deck_error(replace(kPiston1d, "velocity = 0.5 }", "velocity = 20.0 }"));
  EXPECT_HAS(e, "boundary.left.velocity");
  EXPECT_HAS(e, "past its far side");
}

TEST(PistonDeck, HeldFaceAcrossFromAPistonIsRefused) {
  // The piston carries the grid, and the face across from it with it.
  const std::string e =
      deck_error(replace(kPiston1d, "left = { type = \"piston\", velocity = 0.5 }",
                         "left = { type = \"piston\", velocity = 0.5 }\nright = { type = \"fixed\" }"));
  EXPECT_HAS(e, "boundary.right.type");
  EXPECT_HAS(e, "must be free across from the piston on left");
  const std::string two = deck_error(replace(kPlate2d, "[scheme]", R"([boundary]
x_lower = { type = "piston", velocity = 0.5 }
x_upper = { type = "piston", velocity = 0.5 }
[scheme])"));
  EXPECT_HAS(two, "boundary.x_lower.type");  // each is across from the other
  EXPECT_HAS(two, "must be free across from the piston on x_upper");
}

TEST(PistonDeck, ItsSpeedCountsInTheCflCheck) {
  // dt = 0.015 is inside the CFL limit of the bar at rest (dx / c = 0.1 / 5.12 = 0.0195),
  // not inside dx / (c + 5) = 0.0099 with a piston at 5 km/s.
  const std::string e = deck_error(replace(replace(kPiston1d, "velocity = 0.5 }", "velocity = 5.0 }"), "dt = 1e-2",
                                           "dt = 1.5e-2"));
  EXPECT_HAS(e, "exceeds the CFL limit");
}

TEST(PistonDeck, ValueIsNotAPistonKey) {
  EXPECT_HAS(deck_error(replace(kPiston1d, "velocity = 0.5 }", "velocity = 0.5, value = 0.5 }")),
             "boundary.left.value");
}

TEST(GaugeDeck, GaugesRead) {
  const auto c = mpmx::app::read_mpm_deck_text(kPlate2d);
  ASSERT_EQ(c.gauges.size(), 2u);
  EXPECT_EQ(c.gauges[0].kind, mpmx::app::GaugeConfig::Kind::point);
  EXPECT_EQ(c.gauges[0].at[0], 4.5);
  EXPECT_EQ(c.gauges[1].kind, mpmx::app::GaugeConfig::Kind::free_surface);
  EXPECT_EQ(c.gauges[1].body, 1);
  EXPECT_EQ(c.gauges[1].face, 1);
  EXPECT_EQ(c.gauges[1].every, 10);
  const auto one = mpmx::app::read_mpm_deck_text(kPiston1d);
  EXPECT_EQ(one.gauges.at(0).name, "1");  // gauge_1.csv
}

TEST(GaugeDeck, PositionOutsideTheBodiesIsRefused) {
  const std::string e = deck_error(replace(kPlate2d, "at = [4.5, 0.05]", "at = [10.5, 0.05]"));
  EXPECT_HAS(e, "gauge");
  EXPECT_HAS(e, "at");
  EXPECT_HAS(e, "[10.5, 0.05] lies outside the material (every [[body]])");
}

TEST(GaugeDeck, PositionOffTheGridIsRefused) {
  EXPECT_HAS(deck_error(replace(kPiston1d, "at = 5.0", "at = 12.0")), "[12] lies outside the material (the grid)");
}

TEST(GaugeDeck, UnknownFaceIsRefused) {
  const std::string e = deck_error(replace(kPlate2d, "face = \"x_upper\"", "face = \"z_upper\""));
  EXPECT_HAS(e, "face");
  EXPECT_HAS(e, "z_upper");
}

TEST(GaugeDeck, UnknownBodyIsRefusedWithTheNames) {
  EXPECT_HAS(deck_error(replace(kPlate2d, "body = \"target\"", "body = \"tagret\"")),
             "no [[body]] is called tagret: the deck's are flyer, target");
}

TEST(GaugeDeck, BodyNamesAreUnique) {
  EXPECT_HAS(deck_error(replace(kPlate2d, "name = \"target\"", "name = \"flyer\"")), "[[body]] 0 is called flyer too");
}

TEST(GaugeDeck, SeveralBodiesNeedTheBodyNamed) {
  EXPECT_HAS(deck_error(replace(kPlate2d, "body = \"target\"\n", "")), "says whose face it is");
}

TEST(GaugeDeck, NamesAreFileNamesAndUnique) {
  EXPECT_HAS(deck_error(replace(kPlate2d, "name = \"mid\"", "name = \"a/b\"")), "letters, digits, _ and - only");
  EXPECT_HAS(deck_error(replace(kPlate2d, "name = \"mid\"", "name = \"rear\"")), "another [[gauge]] is called rear");
}

TEST(GaugeDeck, UnknownKeyIsRefused) {
  EXPECT_HAS(deck_error(replace(kPlate2d, "every = 10", "evry = 10")), "unknown key 'gauge");
}

// A velocity face that pushes into the material gets a note: a drive is a piston. One
// that oscillates about rest (ADMPM's wave drive) or pushes no material gets none.
TEST(PistonGaugeCheck, PushingVelocityFaceGetsANote) {
  using mpmx::app::describe_pistons_and_gauges;
  using mpmx::app::read_mpm_deck_text;
  auto notes = [](const std::string& deck) {
    std::string all;
    for (const auto& line : describe_pistons_and_gauges(read_mpm_deck_text(deck))) all += line + "\n";
    return all;
  };
  const std::string pushing = notes(replace(kPiston1d, "type = \"piston\", velocity = 0.5", "type = \"velocity\", value = 0.5"));
  EXPECT_HAS(pushing, "note: boundary.left is a velocity face pushing into the material at 0.5");
  EXPECT_HAS(pushing, "a drive is type = \"piston\"");
  const std::string right = notes(replace(kPiston1d, "left = { type = \"piston\", velocity = 0.5 }",
                                          "right = { type = \"velocity\", value = -0.5 }"));
  EXPECT_HAS(right, "note: boundary.right is a velocity face pushing into the material at 0.5");
  EXPECT_EQ(notes(replace(kPiston1d, "type = \"piston\", velocity = 0.5",
                          "type = \"velocity\", amplitude = 0.01, omega = 10.0"))
                .find("note:"),
            std::string::npos);
  EXPECT_EQ(notes(replace(kPiston1d, "type = \"piston\", velocity = 0.5", "type = \"velocity\", value = -0.5"))
                .find("note:"),
            std::string::npos);  // pulls
  // 2-D: the flyer reaches x_lower, nothing reaches x_upper (the target ends at 9 of 12).
  const std::string plate = R"([boundary]
x_lower = { type = "velocity", value = [0.5, 0.0] }
x_upper = { type = "velocity", value = [-0.5, 0.0] }
[scheme])";
  const std::string two = notes(replace(kPlate2d, "[scheme]", plate));
  EXPECT_HAS(two, "note: boundary.x_lower is a velocity face pushing into the material at 0.5");
  EXPECT_EQ(two.find("boundary.x_upper"), std::string::npos);
}

TEST(PistonGaugeCheck, CheckDescribesThePistonAndTheGauges) {
  const auto piston = mpmx::test::run_cli(std::string("check ") + MPMX_SOURCE_DIR + "/examples/C1_piston_elastic_1d.toml");
  EXPECT_EQ(piston.status, 0) << piston.output;
  EXPECT_HAS(piston.output,
             "piston on left: moves at 0.5 into the grid; its face is 3 in at time.end, the grid carried with it");
  const auto gauges = mpmx::test::run_cli(std::string("check ") + MPMX_SOURCE_DIR + "/examples/C2_plate_impact_gauges.toml");
  EXPECT_EQ(gauges.status, 0) << gauges.output;
  EXPECT_HAS(gauges.output, "gauge target_mid: the material point nearest [4.5, 0.03]");
  EXPECT_HAS(gauges.output, "-> gauge_target_mid.csv");
  EXPECT_HAS(gauges.output, "gauge rear_surface: free-surface velocity: the mean of the outermost points of target's "
                            "x_upper face, every 1 step -> gauge_rear_surface.csv");
}
