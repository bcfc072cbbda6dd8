// ctest-cost: 1
// `check`'s first line counts bodies in words ("1 body", none: the grid filled), and a
// deck may leave out [particles], whose keys all have defaults (2 per cell and axis).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "cli_util.hpp"
#include "mpm_deck_test_util.hpp"

namespace {

const char* kGrid2d = R"(
[case]
id = "wording"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [1.0, 1.0]
cells = [10, 10]
[scheme]
name = "mpm"
[material]
model = "linear_elastic"
youngs_modulus = 1.0
[time]
dt = 0.01
end = 0.1
)";

mpmx::test::CliResult check(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return mpmx::test::run_cli("check " + path);
}

}  // namespace

TEST(CheckWording, ADeckWithoutParticlesTakesTheDefaultAndBodiesAreCountedInWords) {
  const auto none = check("no_particles.toml", kGrid2d);
  EXPECT_EQ(none.status, 0) << none.output;
  EXPECT_HAS(none.output, "10 x 10 cells, 2 x 2 points per cell, no [[body]]: the grid filled, 10 steps");
  const auto one = check("one_body.toml", std::string(kGrid2d) +
                                              "[[body]]\nshape = \"box\"\nlower = [0.0, 0.0]\nupper = [0.5, 1.0]\n");
  EXPECT_EQ(one.status, 0) << one.output;
  EXPECT_HAS(one.output, ", 1 body, 10 steps");
  const auto two = check("two_bodies.toml", std::string(kGrid2d) +
                                                "[[body]]\nshape = \"box\"\nlower = [0.0, 0.0]\nupper = [0.5, 1.0]\n"
                                                "[[body]]\nshape = \"box\"\nlower = [0.5, 0.0]\nupper = [1.0, 1.0]\n");
  EXPECT_EQ(two.status, 0) << two.output;
  EXPECT_HAS(two.output, ", 2 bodies, 10 steps");
}
