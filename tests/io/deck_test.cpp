// Deck validation: every kind of bad input gives a message naming key, value, reason.
#include <gtest/gtest.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

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
