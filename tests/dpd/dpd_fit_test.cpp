// The pieces of the MD-to-DPD fit (D0): Nelder-Mead finds a known minimum
// deterministically; the static lattice pressure equals the virial pressure of the DPD
// engine on the perfect lattice at rest; the zero crossing of an isotherm; the potential
// file `fit-dpd` writes reads back, through a deck's `[potential] file`, to the same
// parameters bit for bit. (The full D0 runs in dpd_fit_d0_test, label slow.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "dpd_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/dpd/config.hpp"
#include "mpmx/dpd/fit_config.hpp"
#include "mpmx/dpd/isotherm.hpp"
#include "mpmx/dpd/nelder_mead.hpp"

namespace {

using namespace mpmx;
namespace fs = std::filesystem;

TEST(DpdFit, NelderMeadFindsTheRosenbrockMinimumDeterministically) {
  auto rosen = [](const std::vector<double>& x) {
    return 100 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1 - x[0], 2);
  };
  const auto a = dpd::nelder_mead(rosen, {-1.2, 1.0}, {0.1, 0.1}, 5000, 1e-20);
  const auto b = dpd::nelder_mead(rosen, {-1.2, 1.0}, {0.1, 0.1}, 5000, 1e-20);
  EXPECT_NEAR(a.x[0], 1.0, 1e-5);
  EXPECT_NEAR(a.x[1], 1.0, 1e-5);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.evaluations, b.evaluations);
}

TEST(DpdFit, StaticLatticePressureIsTheEnginesVirialPressure) {
  for (double a : {6.9, 7.23, 7.5}) {
    dpd::Particles p = dpd::fcc_block({4, 4, 4}, a, {0, 0, 0}, test::kCuMesoMass, 0, 1);
    dpd::DpdParams par;  // gamma 0: conservative only, particles at rest
    const dpd::System s(p, test::cube(4 * a), test::cu_meso_morse(12.0), par, {.skin = 1.0});
    const double engine = s.pressure_gpa();
    const double lattice = dpd::static_lattice_pressure(test::cu_meso_morse(12.0), a);
    EXPECT_NEAR(lattice, engine, 1e-9 * (std::abs(engine) + 1.0)) << "a = " << a;
  }
}

TEST(DpdFit, ZeroPressureDensityInterpolates) {
  EXPECT_NEAR(dpd::zero_pressure_density({1.1, 0.9, 1.0}, {3.0, -1.0, 1.0}), 0.95, 1e-12);
  EXPECT_TRUE(std::isnan(dpd::zero_pressure_density({0.9, 1.0}, {1.0, 2.0})));
}

TEST(DpdFit, PotentialFileReadsBackThroughADeck) {
  const fs::path dir = fs::temp_directory_path() / ("mpmx_dpd_fit_" + std::to_string(getpid()));
  fs::create_directories(dir);
  dpd::MorsePotential m;
  m.d0 = 2.718281828459045, m.alpha = 0.6931471805599453, m.r0 = 5.1234567890123456, m.rc = 12.0;
  m.update_offset();
  dpd::write_potential_file((dir / "fitted.toml").string(), m, "test\nsecond line");
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
  const dpd::DpdConfig c = dpd::read_dpd_config(deck);
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
    dpd::read_dpd_config(bad);
    ADD_FAILURE() << "no error for a missing potential file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("potential.file"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace

namespace {

TEST(DpdFit, IsothermsAreTheSameForAnyThreadCount) {
  dpd::DpdIsothermOptions o;
  o.cells = 3, o.heat_capacity = 21 * 8.617343e-5, o.equilibrate_steps = 50, o.sample_steps = 100;
  o.threads = 1;
  const auto a = dpd::dpd_isotherm(test::cu_meso_morse(12.0), {7.1, 7.3}, o);
  o.threads = 2;
  const auto b = dpd::dpd_isotherm(test::cu_meso_morse(12.0), {7.1, 7.3}, o);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(a[k].pressure, b[k].pressure);
    EXPECT_EQ(a[k].temperature, b[k].temperature);
  }
}

}  // namespace
