// The Born constants of the DPD lattice (the continuum side of D3): the constants of a
// pair potential obey the Cauchy relation C12 = C44 and, at the lattice constant of zero
// static pressure, equal the stress-strain slopes of the static lattice measured through
// dpd::System's virial.
#include <gtest/gtest.h>

#include <cmath>

#include "dpd_test_util.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/elastic.hpp"

using namespace mpmx;

TEST(DpdBorn, ConstantsMatchTheStaticLatticeStressSlopes) {
  const dpd::PairPotential pot = test::cu_meso_morse();
  // The lattice constant of zero static pressure, by bisection.
  double lo = 6.0, hi = 9.0;
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    (dpd::fcc_born_constants(pot, mid).pressure > 0 ? lo : hi) = mid;
  }
  const double a0 = 0.5 * (lo + hi);
  const dpd::LatticeConstants k = dpd::fcc_born_constants(pot, a0);
  EXPECT_NEAR(k.c12, k.c44, 1e-12 * k.c11);
  EXPECT_GT(k.c11, k.c12);
  // sigma(eps_xx) of the static lattice (periodic, at rest) by central differences.
  auto stress = [&](double exx) {
    const int n = 5;
    dpd::Particles p = dpd::fcc_block({n, n, n}, a0, {0, 0, 0}, test::kCuMesoMass, 0, 1);
    for (auto& x : p.x) x *= 1 + exx;
    dpd::Domain d = test::cube(n * a0);
    d.box.lx *= 1 + exx;
    dpd::DpdParams par;
    dpd::System s(p, d, pot, par);
    return s.stress_gpa();
  };
  const double h = 1e-4;
  const auto sp = stress(h), sm = stress(-h);
  const double c11 = (sp[0] - sm[0]) / (2 * h) / units::eV_per_A3_in_GPa;
  const double c12 = (sp[4] - sm[4]) / (2 * h) / units::eV_per_A3_in_GPa;
  // Cauchy stress of a uniaxial stretch: d sigma_xx / d eps = C11 - P (P = 0 here).
  EXPECT_NEAR(c11, k.c11, 2e-4 * k.c11);
  EXPECT_NEAR(c12, k.c12, 2e-4 * k.c11);
}
