// The strained-box constants (multiscale/strained_box.hpp): at 0 K they are the Born
// lattice sums of dpd/elastic.hpp (the constants_from = "potential" path) to 1e-6, for
// the DPD engine's mesoparticle crystal at any density (the prestress terms) and for the
// MD engine's crystal of the same pair (LJ 12-6 as the n-m form); at a temperature the
// same numbers for any thread count. (The 298 K Sutton-Chen constants, 500 against 4,000
// atoms, are in strained_box_thermal_test, label slow.)
#include <gtest/gtest.h>

#include <cmath>

#include "../dpd/dpd_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/elastic.hpp"
#include "mpmx/md/potential/lj.hpp"
#include "mpmx/md/potential/sutton_chen.hpp"
#include "mpmx/multiscale/strained_box.hpp"

using namespace mpmx;

namespace {

void expect_born(const multiscale::CubicConstants& c, const dpd::PairPotential& pair, double a) {
  const dpd::LatticeConstants born = dpd::fcc_born_constants(pair, a);
  const double c11 = born.c11 * units::eV_per_A3_in_GPa, c12 = born.c12 * units::eV_per_A3_in_GPa;
  EXPECT_NEAR(c.c11, c11, 1e-6 * std::abs(c11)) << "a = " << a;
  EXPECT_NEAR(c.c12, c12, 1e-6 * std::abs(c12)) << "a = " << a;
  EXPECT_NEAR(c.pressure, born.pressure * units::eV_per_A3_in_GPa, 1e-9 * std::abs(c11)) << "a = " << a;
}

}  // namespace

TEST(StrainedBox, StaticDpdCrystalGivesTheBornConstantsAtAnyDensity) {
  const dpd::PairPotential pair = test::cu_meso_morse(12.0);
  for (double a : {7.0, 7.293, 7.6}) {  // compressed, near zero pressure, stretched
    multiscale::StrainedBoxOptions o;
    o.cells = 4;
    expect_born(multiscale::dpd_strained_constants(pair, a, o), pair, a);
  }
}

TEST(StrainedBox, StaticMdCrystalOfThePairGivesTheBornConstants) {
  md::LjSpec lj;  // argon-like
  lj.epsilon = 0.0104, lj.sigma = 3.4, lj.cutoff = 8.5, lj.mass = 39.95;
  dpd::NmPotential nm;  // the same pair: 4 eps [(s/r)^12 - (s/r)^6] = eps [(r0/r)^12 - 2 (r0/r)^6]
  nm.e0 = lj.epsilon, nm.r0 = std::pow(2.0, 1.0 / 6.0) * lj.sigma, nm.n = 12, nm.m = 6, nm.rc = lj.cutoff;
  nm.update_offset();
  for (double a : {5.2, 5.4}) {
    multiscale::StrainedBoxOptions o;
    o.cells = 4;
    expect_born(multiscale::md_strained_constants(md::Potential(lj), a, o), nm, a);
  }
}

TEST(StrainedBox, ThermalConstantsAreTheSameForAnyThreadCount) {
  md::SuttonChenSpec sc;
  sc.epsilon = 1.2382e-2, sc.a = 3.61, sc.c = 39.432, sc.n = 9, sc.m = 6, sc.cutoff = 7.0, sc.mass = 63.546;
  multiscale::StrainedBoxOptions o;
  o.cells = 3, o.temperature = 298, o.equilibrate_steps = 100, o.sample_steps = 100;
  o.threads = 1;
  const auto one = multiscale::md_strained_constants(md::Potential(sc), 3.64, o);
  o.threads = 2;
  const auto two = multiscale::md_strained_constants(md::Potential(sc), 3.64, o);
  EXPECT_EQ(one.c11, two.c11);
  EXPECT_EQ(one.c12, two.c12);
  EXPECT_GT(one.c11, one.c12);
  EXPECT_GT(one.c12, 0.0);
}

TEST(StrainedBox, OutOfRangeInputIsRefused) {
  multiscale::StrainedBoxOptions o;
  o.strain = 0.5;
  EXPECT_THROW(multiscale::dpd_strained_constants(test::cu_meso_morse(12.0), 7.2, o), InputError);
  o.strain = 0;
  o.cells = 0;
  EXPECT_THROW(multiscale::dpd_strained_constants(test::cu_meso_morse(12.0), 7.2, o), InputError);
}
