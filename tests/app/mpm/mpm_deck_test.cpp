// Continuum deck validation: each kind of bad input names the key, the value and the
// reason; `mpmx check` exits non-zero and `mpmx run` writes nothing on a bad deck.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpm_deck_test_util.hpp"

namespace {

const char* kGoodMpmDeck = R"(
[case]
id = "T"
[grid]
upper = 1.0
cells = 10
[particles]
per_cell = 2
[scheme]
name = "ddmp"
[material]
model = "linear_elastic"
youngs_modulus = 1.0
[time]
dt = 1e-3
end = 0.1
)";

}  // namespace

using mpmx::test::mpm_deck_error;
using mpmx::test::replace;

TEST(MpmDeck, GoodDeckReads) {
  const auto c = mpmx::app::read_mpm_deck_text(kGoodMpmDeck);
  EXPECT_EQ(c.cells, 10);
  EXPECT_EQ(c.steps(), 100);
}

TEST(MpmDeck, MisspelledKey) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "per_cell", "per_cel")),
             "unknown key 'particles.per_cel' (did you mean 'per_cell'?)");
}

TEST(MpmDeck, WrongType) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "cells = 10", "cells = 10.5")),
             "key 'grid.cells' = 10.5: expected an integer, got a number");
}

TEST(MpmDeck, MissingValue) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "youngs_modulus = 1.0", "")),
             "key 'material.youngs_modulus' is missing");
}

TEST(MpmDeck, NegativeDensity) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "youngs_modulus = 1.0", "youngs_modulus = 1.0\ndensity = -2.0")),
             "key 'material.density' = -2: must be positive");
}

TEST(MpmDeck, ZeroCells) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "cells = 10", "cells = 0")),
             "key 'grid.cells' = 0: out of range: must be an integer from 1 to");
}

TEST(MpmDeck, TimeStepAboveCfl) {
  EXPECT_HAS(mpm_deck_error(replace(replace(kGoodMpmDeck, "dt = 1e-3", "dt = 0.2"), "end = 0.1", "end = 0.4")),
             "key 'time.dt' = 0.2: exceeds the CFL limit");
}

TEST(MpmDeck, UnknownScheme) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "\"ddmp\"", "\"gimp\"")),
             "key 'scheme.name' = \"gimp\": not one of mpm, ugimp, cpgimp, cpdi, ddmp, ddmp_subpoints");
}

TEST(MpmDeck, SubpointsOnlyWithSubpointScheme) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "name = \"ddmp\"", "name = \"ddmp\"\nsubpoints = 8")),
             "only ddmp_subpoints uses sub-points");
}

TEST(MpmDeck, EndNotWholeSteps) {
  EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "end = 0.1", "end = 0.10005")),
             "key 'time.end' = 0.10005: is not a whole number of steps");
}

TEST(MpmDeck, EveryErrorAtOnceWithLines) {
  const std::string e = mpm_deck_error(replace(replace(kGoodMpmDeck, "cells = 10", "cells = -1"), "per_cell = 2",
                                               "per_cell = 2\ncolour = \"red\""));
  EXPECT_HAS(e, "t.toml:6: key 'grid.cells' = -1");
  EXPECT_HAS(e, "unknown key 'particles.colour'");
}

TEST(MpmCli, CheckFailsAndRunWritesNothing) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "mpmx_deck_cli_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path deck = dir / "bad.toml";
  std::ofstream(deck) << replace(kGoodMpmDeck, "cells = 10", "cells = 0");
  const std::string bin = MPMX_BINARY;
  const int check = std::system((bin + " check " + deck.string() + " >/dev/null 2>&1").c_str());
  EXPECT_NE(check, 0);
  const fs::path out = dir / "out";
  const int run = std::system((bin + " run " + deck.string() + " --out " + out.string() + " >/dev/null 2>&1").c_str());
  EXPECT_NE(run, 0);
  EXPECT_FALSE(fs::exists(out));
  std::ofstream(deck) << kGoodMpmDeck;
  EXPECT_EQ(std::system((bin + " check " + deck.string() + " >/dev/null").c_str()), 0);
  fs::remove_all(dir);
}

TEST(MpmDeck, StepFrontOffTheGrid) {
  for (const char* profile : {"step", "tanh"}) {
    const std::string v = std::string("[initial.velocity]\nprofile = \"") + profile +
                          "\"\nleft = 0.1\nright = 0.0\nat = 5.0\n" + (profile[0] == 't' ? "cells = 2\n" : "");
    EXPECT_HAS(mpm_deck_error(replace(kGoodMpmDeck, "[time]", v + "[time]")),
               "key 'initial.velocity.at' = 5: must lie on the grid, from 0 to 1");
    const std::string on = replace(v, "at = 5.0", "at = 0.5");
    EXPECT_EQ(mpm_deck_error(replace(kGoodMpmDeck, "[time]", on + "[time]")), "(no error)");
  }
}
