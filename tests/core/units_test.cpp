// core/units: the conversions between MD's metal units and the continuum unit systems.
#include <gtest/gtest.h>

#include "mpmx/core/units.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "../md/md_test_util.hpp"

namespace {

using namespace mpmx;

TEST(Units, MetalPressure) {
  EXPECT_NEAR(units::eV_per_A3_in_GPa, 160.21766, 1e-5);
  EXPECT_NEAR(units::lammps_nktv2p / 1e4, units::eV_per_A3_in_GPa, 2e-5);  // LAMMPS rounds to 8 digits
}

TEST(Units, NamedSystems) {
  const auto nm = units::unit_system("nm_ps_GPa");
  ASSERT_TRUE(nm.has_value());
  EXPECT_DOUBLE_EQ(nm->velocity_A_per_ps(), 10.0);  // 1 nm/ps = 1 km/s = 10 A/ps
  const auto metal = units::unit_system("metal");
  ASSERT_TRUE(metal.has_value());
  EXPECT_NEAR(metal->stress_GPa, 0.0166053907, 1e-10);  // 1 amu/(A ps^2)
  const auto si = units::unit_system("SI");
  ASSERT_TRUE(si.has_value());
  EXPECT_DOUBLE_EQ(si->stress_GPa, 1e-9);
  EXPECT_FALSE(units::unit_system("furlongs").has_value());
  EXPECT_NE(units::unit_system_names().find("mm_us_GPa"), std::string::npos);
}

TEST(Units, CopperDensityInEveryUnitSystem) {
  const md::PotentialSpec cu = test::copper_spec();
  // 8.9356 g/cm^3: nm_ps_GPa and mm_us_GPa measure density in g/cm^3, SI in kg/m^3.
  EXPECT_NEAR(multiscale::md_closure_properties(cu, *units::unit_system("nm_ps_GPa")).density, 8.9356, 1e-4);
  EXPECT_NEAR(multiscale::md_closure_properties(cu, *units::unit_system("mm_us_GPa")).density, 8.9356, 1e-4);
  const auto si = multiscale::md_closure_properties(cu, *units::unit_system("SI"));
  EXPECT_NEAR(si.density, 8935.6, 0.1);
  EXPECT_NEAR(si.sound_speed, 4360.0, 2.0);  // sqrt(C11 / rho), m/s
  EXPECT_NEAR(multiscale::md_closure_properties(cu, *units::unit_system("metal")).density, 5.3812, 1e-4);
}

}  // namespace
