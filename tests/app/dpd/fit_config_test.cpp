// The potential file `fit-dpd` writes (app/dpd/fit_config.hpp) reads back, through a DPD
// deck's `[potential] file`, to the same parameters bit for bit.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/dpd/fit_config.hpp"
#include "mpmx/core/error.hpp"

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
cells = [2, 2, 2]
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
