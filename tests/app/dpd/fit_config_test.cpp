// The potential file `fit-dpd` writes (app/dpd/fit_config.hpp) reads back, through a DPD
// deck's `[potential] file`, to the same parameters bit for bit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/dpd/fit_config.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"

using namespace mpmx;
namespace fs = std::filesystem;

TEST(FitConfig, PotentialFileReadsBackThroughADeck) {
  const fs::path dir = fs::temp_directory_path() / ("mpmx_dpd_fit_" + std::to_string(getpid()));
  fs::create_directories(dir);
  dpd::MorsePotential m;
  m.d0 = 2.718281828459045, m.alpha = 0.6931471805599453, m.r0 = 5.1234567890123456, m.rc = 12.0;
  m.update_offset();
  app::dpd::write_potential_file((dir / "fitted.toml").string(), m, "test\nsecond line");
  std::ofstream(dir / "deck.toml") << R"(
[case]
id = "t"
[potential]
file = "fitted.toml"
[[block]]
constant = 7.23
cells = [4, 4, 4]  # twice the 12 A cutoff: a periodic box DPD can run
mass = 508.368
[dpd]
gamma = 0.2
temperature = 298.0
[run]
dt = 0.005
steps = 1
)";
  io::Deck deck = io::Deck::from_file((dir / "deck.toml").string());
  const app::dpd::DpdConfig c = app::dpd::read_dpd_config(deck);
  const auto* got = std::get_if<dpd::MorsePotential>(&c.potential);
  ASSERT_NE(got, nullptr);
  EXPECT_EQ(got->d0, m.d0);
  EXPECT_EQ(got->alpha, m.alpha);
  EXPECT_EQ(got->r0, m.r0);
  EXPECT_EQ(got->rc, m.rc);
  EXPECT_EQ(got->offset, m.offset);
  // A missing file is an input error naming the key.
  std::ofstream(dir / "bad.toml") << "[case]\nid = \"t\"\n[potential]\nfile = \"nope.toml\"\n[[block]]\nconstant = 7.23\n"
                                     "cells = [2, 2, 2]\nmass = 1.0\n[dpd]\ngamma = 0.2\ntemperature = 1.0\n[run]\ndt = 0.005\n"
                                     "steps = 1\n";
  io::Deck bad = io::Deck::from_file((dir / "bad.toml").string());
  try {
    app::dpd::read_dpd_config(bad);
    ADD_FAILURE() << "no error for a missing potential file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("potential.file"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Hostile input (issue 31): every integer of a fit-dpd deck is range-checked as read, not
// cut to 32 bits (4294967298 was read as 2 and passed the 2-40 check).
TEST(FitConfig, IntegersAreRangeCheckedNotWrapped) {
  std::ifstream in(std::string(MPMX_SOURCE_DIR) + "/examples/D0_md_to_dpd_fit.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string base = ss.str();
  for (const auto& [table_key, line] : std::vector<std::pair<std::string, std::string>>{
           {"md.cells", "cells = 5                 # 500 atoms"},
           {"md.sample_steps", "sample_steps = 5000       # pressure every 10 steps"},
           {"densities.points", "points = 11"},
           {"dpd.cells", "cells = 4                 # 256 mesoparticles"},
           {"dpd.iterations", "iterations = 3            # thermal-correction rounds"}}) {
    std::string text = base;
    const auto at = text.find(line);
    ASSERT_NE(at, std::string::npos) << line;
    const std::string key = line.substr(0, line.find(' '));
    text.replace(at, line.size(), key + " = 4294967298");
    auto deck = io::Deck::from_string(text, "D0.toml");
    try {
      app::dpd::read_fit_config(deck);
      ADD_FAILURE() << table_key << " = 4294967298 was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(table_key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("4294967298"), std::string::npos) << e.what();
    }
  }
}

// [elastic] (issue "the MD-to-DPD bridge"): the example deck reads with the MD boxes'
// sizes defaulting to [md]'s; the isotherm-only deck has no elastic targets; a weight
// below 0 or a strain of 20% is refused naming the key.
TEST(FitConfig, ElasticTargetsAreReadAndChecked) {
  const std::string src = std::string(MPMX_SOURCE_DIR) + "/examples/";
  io::Deck plain = io::Deck::from_file(src + "D0_md_to_dpd_fit.toml");
  EXPECT_FALSE(app::dpd::read_fit_config(plain).fit.elastic.on);
  io::Deck deck = io::Deck::from_file(src + "D0_md_to_dpd_fit_elastic.toml");
  const app::dpd::FitConfig c = app::dpd::read_fit_config(deck);
  EXPECT_TRUE(c.fit.elastic.on);
  EXPECT_EQ(c.fit.elastic.weight, 1.0);
  EXPECT_EQ(c.md_elastic.cells, c.md.cells);
  EXPECT_EQ(c.md_elastic.temperature, 298.0);
  EXPECT_EQ(c.md_elastic.strain, 0.01);
  EXPECT_EQ(c.fit.elastic.boxes.cells, c.fit.dpd.cells);
  EXPECT_EQ(c.potential_file, "cu_sc_298K_morse_elastic.toml");
  std::ifstream in(src + "D0_md_to_dpd_fit_elastic.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  for (const auto& [from, to, key] : std::vector<std::array<std::string, 3>>{
           {"weight = 1.0 ", "weight = -1.0 ", "elastic.weight"}, {"strain = 0.01 ", "strain = 0.2 ", "elastic.strain"}}) {
    std::string text = ss.str();
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    auto bad = io::Deck::from_string(text, "D0_elastic.toml");
    try {
      app::dpd::read_fit_config(bad);
      ADD_FAILURE() << to << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// Hostile input (issue 31): a potential file named as one of the fit's own outputs or a
// folder (".", "..", ".staging") is refused at read, before the 10 minutes of the fit.
TEST(FitConfig, PotentialFileCannotBeAnOutputOrAFolder) {
  std::ifstream in(std::string(MPMX_SOURCE_DIR) + "/examples/D0_md_to_dpd_fit.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string line = "potential_file = \"cu_sc_298K_morse.toml\"";
  for (const std::string name : {"run.json", "isotherm.csv", ".", "..", ".staging"}) {
    std::string text = ss.str();
    const auto at = text.find(line);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, line.size(), "potential_file = \"" + name + "\"");
    auto deck = io::Deck::from_string(text, "D0.toml");
    try {
      app::dpd::read_fit_config(deck);
      ADD_FAILURE() << name << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("output.potential_file"), std::string::npos) << e.what();
    }
  }
}

// Every integer of a fit deck through the checked reader: 2^32 + 2 is out of range by name,
// not a count that wrapped; a lattice constant whose lattice sums would not end is refused.
TEST(FitConfig, IntegersAndLatticeConstantAreBounded) {
  std::ifstream in(std::string(MPMX_SOURCE_DIR) + "/tests/fuzz/corpus/fit_deck/minimal.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string good = ss.str();
  auto error_of = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) t.replace(at, from.size(), to);
    try {
      io::Deck d = io::Deck::from_string(t, "fit.toml");
      app::dpd::read_fit_config(d);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of("cells = 5", "cells = 5"), "(no error)");
  for (const auto& [from, key] : std::vector<std::pair<std::string, std::string>>{
           {"cells = 5", "md.cells"},
           {"cells = 4", "dpd.cells"},
           {"points = 11", "densities.points"},
           {"iterations = 3", "dpd.iterations"},
           {"sample_steps = 5000", "md.sample_steps"},
           {"sample_steps = 4000", "dpd.sample_steps"}}) {
    const std::string to = from.substr(0, from.find('=') + 2) + "4294967298";
    const std::string e = error_of(from, to);
    EXPECT_NE(e.find("key '" + key + "' = 4294967298: out of range"), std::string::npos) << e;
  }
  const std::string e = error_of("lattice_constant = 3.61", "lattice_constant = 1e-300");
  EXPECT_NE(e.find("key 'md.lattice_constant' = 1e-300: must lie in [0.5, 100] Angstrom"), std::string::npos) << e;
  // Within that range, atoms closer than a bond (issue 45).
  const std::string close = error_of("lattice_constant = 3.61", "lattice_constant = 1.2");
  EXPECT_NE(close.find("key 'md.lattice_constant' = 1.2: fcc nearest neighbours would be 0.8485 A apart"),
            std::string::npos)
      << close;
}
