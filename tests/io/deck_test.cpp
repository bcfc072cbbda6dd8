// Deck validation: every kind of bad input gives a message naming key, value, reason.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

#include "cli_util.hpp"

using mpmx::InputError;
using mpmx::io::Deck;

namespace {

std::string finish_error(Deck& d) {
  try {
    d.finish();
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(Deck, ReadsTypedValues) {
  auto d = Deck::from_string("[grid]\ncells = 50\nlower = 0.0\n");
  auto g = d.root().table("grid");
  EXPECT_EQ(g.integer("cells"), 50);
  EXPECT_DOUBLE_EQ(g.number("lower"), 0.0);
  EXPECT_DOUBLE_EQ(g.number("upper", 2.5), 2.5);
  EXPECT_NO_THROW(d.finish());
}

TEST(Deck, UnknownKeyIsNamedWithSuggestion) {
  auto d = Deck::from_string("[grid]\ncels = 50\n", "a.toml");
  auto g = d.root().table("grid");
  g.integer("cells", 10);
  std::string e = finish_error(d);
  EXPECT_NE(e.find("a.toml:2"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown key 'grid.cels'"), std::string::npos) << e;
  EXPECT_NE(e.find("did you mean 'cells'"), std::string::npos) << e;
}

TEST(Deck, WrongTypeNamesKeyValueAndExpectation) {
  auto d = Deck::from_string("[grid]\ncells = \"fifty\"\n");
  d.root().table("grid").integer("cells");
  std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'grid.cells' = \"fifty\": expected an integer, got a string"),
            std::string::npos)
      << e;
}

TEST(Deck, MissingValueIsAnError) {
  auto d = Deck::from_string("[material]\n");
  d.root().table("material").number("density");
  std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'material.density' is missing"), std::string::npos) << e;
}

TEST(Deck, ImpossibleValueGivesReason) {
  auto d = Deck::from_string("[material]\ndensity = -1.0\n");
  auto m = d.root().table("material");
  m.positive("density", m.number("density"));
  std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'material.density' = -1: must be positive"), std::string::npos) << e;
}

TEST(Deck, ChoiceListsAllowedNames) {
  auto d = Deck::from_string("[scheme]\nname = \"gimp\"\n");
  d.root().table("scheme").choice("name", {"mpm", "ugimp", "cpgimp"});
  std::string e = finish_error(d);
  EXPECT_NE(e.find("\"gimp\": not one of mpm, ugimp, cpgimp"), std::string::npos) << e;
}

TEST(Deck, SyntaxErrorNamesLine) {
  try {
    Deck::from_string("[grid]\ncells = = 3\n", "b.toml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("b.toml:2"), std::string::npos) << e.what();
  }
}

TEST(Deck, AllErrorsReportedTogether) {
  auto d = Deck::from_string("[a]\nx = -1\ny = \"s\"\nz = 1\n");
  auto a = d.root().table("a");
  a.positive("x", a.number("x"));
  a.number("y");
  std::string e = finish_error(d);
  EXPECT_NE(e.find("'a.x'"), std::string::npos);
  EXPECT_NE(e.find("'a.y'"), std::string::npos);
  EXPECT_NE(e.find("unknown key 'a.z'"), std::string::npos);
}

// ------------------------------------------------ checked integers (issue 17)

namespace {

std::int64_t read_int(const std::string& text, std::string& error, std::int64_t lo = 1,
                      std::int64_t hi = 1000000) {
  auto d = Deck::from_string(text, "i.toml");
  const std::int64_t v = d.root().table("grid").integer("cells", lo, hi);
  error = finish_error(d);
  return v;
}

using mpmx::test::count;

}  // namespace

TEST(DeckInteger, InRangeIsRead) {
  std::string e;
  EXPECT_EQ(read_int("[grid]\ncells = 50\n", e), 50);
  EXPECT_EQ(e, "");
}

TEST(DeckInteger, BeyondThirtyTwoBitsIsRefusedNotWrapped) {
  // 4294967346 = 2^32 + 50: wrapped to 32 bits it would read as 50 cells.
  std::string e;
  const auto v = read_int("[grid]\ncells = 4294967346\n", e);
  EXPECT_NE(e.find("i.toml:2: key 'grid.cells' = 4294967346: out of range: must be an integer from 1 to 1000000"),
            std::string::npos)
      << e;
  EXPECT_GE(v, 1);
  EXPECT_LE(v, 1000000);  // what is returned on an error is still inside the limits
}

TEST(DeckInteger, FloatIsATypeErrorNotARangeError) {
  std::string e;
  read_int("[grid]\ncells = 1e12\n", e);
  EXPECT_NE(e.find("key 'grid.cells' = 1e+12: expected an integer, got a number"), std::string::npos) << e;
  EXPECT_EQ(e.find("at least"), std::string::npos) << e;
  EXPECT_EQ(e.find("out of range"), std::string::npos) << e;
  EXPECT_EQ(count(e, "grid.cells"), 1u) << e;
  read_int("[grid]\ncells = 4.0\n", e);
  EXPECT_NE(e.find("key 'grid.cells' = 4.0: expected an integer, got a number (write 4 without a decimal point"),
            std::string::npos)
      << e;
  read_int("[grid]\ncells = 10.5\n", e);
  EXPECT_NE(e.find("key 'grid.cells' = 10.5: expected an integer, got a number (it has a fractional part)"),
            std::string::npos)
      << e;
  // The unchecked reader says the same.
  auto d = Deck::from_string("[grid]\ncells = 1e12\n");
  d.root().table("grid").integer("cells");
  e = finish_error(d);
  EXPECT_NE(e.find("key 'grid.cells' = 1e+12: expected an integer, got a number"), std::string::npos) << e;
}

TEST(DeckInteger, OneSidedLimitsAndMissingKeys) {
  std::string e;
  read_int("[grid]\ncells = -3\n", e, 0, std::numeric_limits<std::int64_t>::max());
  EXPECT_NE(e.find("key 'grid.cells' = -3: out of range: must be an integer >= 0"), std::string::npos)
      << e;
  read_int("[grid]\n", e);
  EXPECT_NE(e.find("key 'grid.cells' is missing: expected an integer from 1 to 1000000"), std::string::npos) << e;
  // Optional: the fallback when absent; checked when present.
  auto d = Deck::from_string("[grid]\nper_cell = 0\n");
  auto g = d.root().table("grid");
  EXPECT_EQ(g.integer("cells", 7, 1, 10), 7);
  EXPECT_EQ(g.integer_int("per_cell", 2, 1, 1000), 1);  // out of range: clamped into the limits
  e = finish_error(d);
  EXPECT_NE(e.find("key 'grid.per_cell' = 0: out of range: must be an integer from 1 to 1000"), std::string::npos)
      << e;
}

TEST(DeckInteger, IntHelperNeverNarrowsUnchecked) {
  auto d = Deck::from_string("[scan]\npoints = 4294967299\n");
  const int v = d.root().table("scan").integer_int("points", 41, 3, 100000);
  EXPECT_GE(v, 3);
  EXPECT_LE(v, 100000);
  const std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'scan.points' = 4294967299: out of range: must be an integer from 3 to 100000"),
            std::string::npos)
      << e;
}

TEST(DeckInteger, ArraysAreCheckedEntryByEntry) {
  auto d = Deck::from_string("[lattice]\na = [4, 4294967346, 4]\nb = [3, 1e12]\nc = [2, 2]\n");
  auto l = d.root().table("lattice");
  EXPECT_TRUE(l.integers("a", 1, 1000).empty());
  EXPECT_TRUE(l.integers("b", 1, 1000).empty());
  EXPECT_EQ(l.integers("c", 1, 1000), (std::vector<std::int64_t>{2, 2}));
  const std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'lattice.a' = [4, 4294967346, 4]: entry 2 = 4294967346: out of range: must be "
                   "an integer from 1 to 1000"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("key 'lattice.b' = [3, 1000000000000]: entry 2 is 1e+12, expected an integer"),
            std::string::npos)
      << e;
}

// ------------------------------------------------ nan and inf (issue 17)

TEST(DeckNumber, NanAndInfAreRefusedNamingTheKey) {
  auto d = Deck::from_string("[run]\na = nan\nb = inf\nc = -inf\nd = +nan\ne = 1.5\n", "n.toml");
  auto r = d.root().table("run");
  for (const char* k : {"a", "b", "c", "d", "e"}) r.number(k);
  const std::string e = finish_error(d);
  EXPECT_NE(e.find("n.toml:2: key 'run.a' = nan: must be a finite number"), std::string::npos) << e;
  EXPECT_NE(e.find("n.toml:3: key 'run.b' = inf: must be a finite number"), std::string::npos) << e;
  EXPECT_NE(e.find("n.toml:4: key 'run.c' = -inf: must be a finite number"), std::string::npos) << e;
  EXPECT_NE(e.find("n.toml:5: key 'run.d'"), std::string::npos) << e;
  EXPECT_EQ(e.find("run.e"), std::string::npos) << e;
}

TEST(DeckNumber, NanInAnArrayIsRefusedNamingTheEntry) {
  auto d = Deck::from_string("[run]\ng = [0, 0, 0, 0, nan, 0, 0, 0, 0]\nt = [1.0, inf]\n");
  auto r = d.root().table("run");
  EXPECT_TRUE(r.numbers("g").empty());
  EXPECT_TRUE(r.numbers("t", {}).empty());
  const std::string e = finish_error(d);
  EXPECT_NE(e.find("key 'run.g' = [0, 0, 0, 0, nan, 0, 0, 0, 0]: entry 5 is nan: every entry must be a finite "
                   "number"),
            std::string::npos)
      << e;
  EXPECT_NE(e.find("key 'run.t' = [1, inf]: entry 2 is inf"), std::string::npos) << e;
}

// ------------------------------------------------ one message per key (issue 17)

TEST(Deck, EachKeyIsReportedOnce) {
  // A missing or mistyped value is not reported again by the range check after it, and
  // the keys of a missing table are not reported one by one.
  auto d = Deck::from_string("[lattice]\nconstant = \"big\"\n[run]\ndt = nan\n");
  auto root = d.root();
  auto lat = root.table("lattice");
  lat.positive("constant", lat.number("constant"));
  auto run = root.table("run");
  run.positive("dt", run.number("dt"));
  run.positive("steps", run.number("steps"));
  auto pot = root.table("potential");
  pot.string("file");
  pot.positive("cutoff", pot.number("cutoff"));
  const std::string e = finish_error(d);
  EXPECT_EQ(count(e, "lattice.constant"), 1u) << e;
  EXPECT_EQ(count(e, "run.dt"), 1u) << e;
  EXPECT_EQ(count(e, "run.steps"), 1u) << e;
  EXPECT_EQ(count(e, "'potential"), 1u) << e;
  EXPECT_EQ(count(e, "\n") + 1, 4u) << e;
}

TEST(Deck, DirectoryOrMissingFileIsNamed) {
  const std::string dir = ::testing::TempDir();
  try {
    Deck::from_file(dir);
    FAIL() << "a directory was read as a deck";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory, not a deck file"), std::string::npos) << e.what();
  }
  try {
    Deck::from_file(dir + "/no_such_deck.toml");
    FAIL() << "a missing file was read as a deck";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_deck.toml: no such deck file"), std::string::npos) << e.what();
  }
}
