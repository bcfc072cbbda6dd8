// The isotherms of the MD-to-DPD fit (multiscale/isotherm.hpp): the static lattice
// pressure equals the virial pressure of the DPD engine on the perfect lattice at rest;
// the zero crossing of an isotherm; the DPDE isotherm the same for any thread count.
// (The full D0 runs in dpd_fit_d0_test, label slow.)
#include <gtest/gtest.h>

#include <cmath>

#include "../dpd/dpd_test_util.hpp"
#include "mpmx/multiscale/isotherm.hpp"

using namespace mpmx;

TEST(Isotherm, StaticLatticePressureIsTheEnginesVirialPressure) {
  for (double a : {6.9, 7.23, 7.5}) {
    dpd::Particles p = dpd::fcc_block({4, 4, 4}, a, {0, 0, 0}, test::kCuMesoMass, 0, 1);
    dpd::DpdParams par;  // gamma 0: conservative only, particles at rest
    const dpd::System s(p, test::cube(4 * a), test::cu_meso_morse(12.0), par, {.skin = 1.0});
    const double engine = s.pressure_gpa();
    const double lattice = multiscale::static_lattice_pressure(test::cu_meso_morse(12.0), a);
    EXPECT_NEAR(lattice, engine, 1e-9 * (std::abs(engine) + 1.0)) << "a = " << a;
  }
}

TEST(Isotherm, ZeroPressureDensityInterpolates) {
  EXPECT_NEAR(multiscale::zero_pressure_density({1.1, 0.9, 1.0}, {3.0, -1.0, 1.0}), 0.95, 1e-12);
  EXPECT_TRUE(std::isnan(multiscale::zero_pressure_density({0.9, 1.0}, {1.0, 2.0})));
}

TEST(Isotherm, IsothermsAreTheSameForAnyThreadCount) {
  multiscale::DpdIsothermOptions o;
  o.cells = 3, o.heat_capacity = 21 * 8.617343e-5, o.equilibrate_steps = 50, o.sample_steps = 100;
  o.threads = 1;
  const auto a = multiscale::dpd_isotherm(test::cu_meso_morse(12.0), {7.1, 7.3}, o);
  o.threads = 2;
  const auto b = multiscale::dpd_isotherm(test::cu_meso_morse(12.0), {7.1, 7.3}, o);
  for (int k = 0; k < 2; ++k) {
    EXPECT_EQ(a[k].pressure, b[k].pressure);
    EXPECT_EQ(a[k].temperature, b[k].temperature);
  }
}
