// ctest-cost: 1
// `check` does its cheap checks first: an oriented crystal's tile is counted from its
// directions and refused past its bound before anything is built (md_closure decks, md
// decks, the library's lattice_tile); prepare = "npt" is stated, run by `run` alone; a
// range error of any key comes before the crystal's constants are worked out.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <toml++/toml.h>

#include "cli_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace {

using namespace mpmx;

#define EXPECT_HAS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

// examples/H5_ta_110_small.toml (bcc Ta along [110], prepare = "npt") edited by `edit`,
// written to the test's folder as `name`.
template <class Edit>
std::string h5_deck(const std::string& name, Edit edit) {
  toml::table t = toml::parse_file(std::string(MPMX_SOURCE_DIR) + "/examples/H5_ta_110_small.toml");
  edit(t);
  t.erase("reference");
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << t;
  return path;
}

toml::array orient(std::array<std::array<int, 3>, 3> o) {
  toml::array a;
  for (const auto& r : o) a.push_back(toml::array{r[0], r[1], r[2]});
  return a;
}

// The sanitizer build's program reserves terabytes of shadow address space: a cap on
// the address space would stop it before main, so there the time bound alone holds.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// `mpmx check` of `deck` with at most 2 GB of address space and 120 s of CPU: a check
// that built the tile or ran the NPT box would be stopped by the caps (status not 0 or
// 2), so each test asserts what check said, never how long it took.
test::CliResult capped_check(const std::string& deck) {
  return test::run_cli_env(kAddressSanitizer ? "ulimit -t 120 &&" : "ulimit -v 2000000 && ulimit -t 120 &&",
                           "check " + deck);
}

}  // namespace

TEST(CheckFirst, ATileIsCountedFromItsDirectionsAndRefusedPastItsBoundBeforeItIsBuilt) {
  particles::LatticeSpec s;
  s.style = particles::LatticeStyle::bcc;
  s.constant = 3.3;
  s.orient = {{{1, 1, 30}, {-1, 1, 0}, {-15, -15, 1}}};
  EXPECT_EQ(particles::lattice_tile_atoms(s), 902);
  EXPECT_EQ(particles::lattice_tile(s).atoms, 902);  // built, it holds what was counted
  EXPECT_EQ(particles::lattice_tile(s).sites.size(), 902u);
  // Large Miller indices: 2e6 and 1e12 atoms, refused from the count alone.
  s.orient = {{{1, 1, 1000}, {-1, 1, 0}, {-500, -500, 1}}};
  EXPECT_EQ(particles::lattice_tile_atoms(s), 2000004);
  EXPECT_HAS(particles::orient_problem(s), "a periodic tile of 2000004 atoms, more than the 1000000 a tile may hold");
  s.style = particles::LatticeStyle::fcc;
  s.orient = {{{1, 1, 1000}, {999, 1, -1}, {-1001, 999001, -998}}};  // the third: the first x the second
  EXPECT_GT(particles::lattice_tile_atoms(s), 1e11);
  try {
    (void)particles::lattice_tile(s);
    ADD_FAILURE() << "built a tile past the bound";
  } catch (const InputError& e) {
    EXPECT_HAS(std::string(e.what()), "more than the 1000000 a tile may hold");
  }
}

TEST(CheckFirst, AnMdClosureOrientationOfAHugeTileIsRefusedAtOnce) {
  const std::string deck = h5_deck("huge_tile.toml", [](toml::table& t) {
    t["material"]["md"].as_table()->insert_or_assign("orient", orient({{{1, 1, 1000}, {-1, 1, 0}, {-500, -500, 1}}}));
    t["material"]["md"].as_table()->insert_or_assign("cells", 1);
  });
  const auto r = capped_check(deck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_HAS(r.output, "key 'material.md.orient' = [[1, 1, 1000], [-1, 1, 0], [-500, -500, 1]]");
  EXPECT_HAS(r.output, "a periodic tile of 2000004 atoms, more than the 1000000 a tile may hold");
}

TEST(CheckFirst, AnMdDeckOrientationOfAHugeTileIsRefusedAtOnce) {
  const std::string deck = ::testing::TempDir() + "huge_tile_md.toml";
  std::ofstream(deck) << "[potential]\nstyle = \"lj\"\nepsilon = 0.4\nsigma = 2.3\ncutoff = 5.0\nmass = 63.5\n"
                         "[lattice]\nconstant = 3.615\ncells = [1]\n"
                         "orient = [[1, 1, 1000], [-1, 1, 0], [-500, -500, 1]]\n[run]\ndt = 0.001\nsteps = 10\n";
  const auto r = capped_check(deck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_HAS(r.output, "key 'lattice.orient'");
  EXPECT_HAS(r.output, "a periodic tile of 1000002 atoms, more than the 1000000 a tile may hold");
}

// The NPT box is the run's: check states it at once, however long it is, and the deck's
// other errors do not wait on it.
TEST(CheckFirst, NptPreparationIsStatedNotRun) {
  const std::string deck = h5_deck("npt_long.toml", [](toml::table& t) {
    t["material"]["md"].as_table()->insert_or_assign("prepare_steps", 100000000);
  });
  const auto r = capped_check(deck);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_HAS(r.output, "prepare: one box by NPT at 10 K and 0 GPa for 100000000 steps when the run starts");
  EXPECT_EQ(r.output.find("prepared by NPT"), std::string::npos) << r.output;
  const std::string bad = h5_deck("npt_long_bad.toml", [](toml::table& t) {
    t["material"]["md"].as_table()->insert_or_assign("prepare_steps", 100000000);
    t["time"].as_table()->insert_or_assign("end", -3.0);
  });
  const auto e = capped_check(bad);
  EXPECT_EQ(e.status, 2) << e.output;
  EXPECT_HAS(e.output, "key 'time.end' = -3: must be positive");
}

// A tile of 80004 atoms takes its potential's equilibrium a minute or more to find: a
// range error elsewhere in the deck is said first, without it.
TEST(CheckFirst, RangeErrorsComeBeforeTheCrystalsConstants) {
  const std::string deck = h5_deck("big_tile_bad_end.toml", [](toml::table& t) {
    t["material"]["md"].as_table()->insert_or_assign("orient", orient({{{1, 1, 200}, {-1, 1, 0}, {-100, -100, 1}}}));
    t["material"]["md"].as_table()->insert_or_assign("cells", 1);
    t["time"].as_table()->insert_or_assign("end", -3.0);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
  });
  const auto r = capped_check(deck);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_HAS(r.output, "key 'time.end' = -3: must be positive");
  EXPECT_EQ(r.output.find("exceeds the CFL limit"), std::string::npos) << r.output;  // no check on unknown constants
}
