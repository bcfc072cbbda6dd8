// Common neighbour analysis (fig. 4) and the Born constants of the DPD lattice (the
// continuum side of D3): a perfect fcc lattice, periodic, is all fcc; an hcp lattice is
// all hcp; a strongly shuffled one has no fcc; the constants of a pair potential obey the
// Cauchy relation C12 = C44 and, at the lattice constant of zero static pressure, equal
// the stress-strain slopes of the static lattice measured through dpd::System's virial.
#include <gtest/gtest.h>

#include <cmath>

#include "dpd_test_util.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/cna.hpp"
#include "mpmx/dpd/elastic.hpp"
#include "mpmx/md/rng.hpp"

namespace {

using namespace mpmx;

TEST(DpdCna, PerfectFccIsFcc) {
  const double a = test::kCoarseLattice;
  dpd::Particles p = dpd::fcc_block({4, 4, 4}, a, {0, 0, 0}, 1.0, 0, 1);
  const auto c = dpd::common_neighbour_analysis(p, test::cube(4 * a), a);
  EXPECT_DOUBLE_EQ(dpd::fcc_fraction(c), 1.0);
}

TEST(DpdCna, HcpIsHcpAndNoiseIsOther) {
  // hcp: a = 5, c = a sqrt(8/3) in an orthogonal cell of 4 sites (a, a sqrt 3, c).
  const double a = 5.0, c = a * std::sqrt(8.0 / 3.0), b = a * std::sqrt(3.0);
  const int nx = 6, ny = 4, nz = 4;
  dpd::Particles p;
  std::int64_t id = 1;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 1.0 / 6, 0.5}, {0, 2.0 / 3, 0.5}};
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        for (const auto& s : basis) p.push_back((i + s[0]) * a, (j + s[1]) * b, (k + s[2]) * c, 1.0, 0, id++);
  dpd::Domain d = test::cube(1);
  d.box.lx = nx * a, d.box.ly = ny * b, d.box.lz = nz * c;
  const auto codes = dpd::common_neighbour_analysis(p, d, a * std::sqrt(2.0));  // nearest neighbours at a
  for (auto code : codes) ASSERT_EQ(code, dpd::kHcp);
  md::RngStream rng(7, 0);
  for (std::size_t i = 0; i < p.size(); ++i) p.x[i] += 0.25 * a * rng.normal(), p.y[i] += 0.25 * a * rng.normal();
  EXPECT_LT(dpd::fcc_fraction(dpd::common_neighbour_analysis(p, d, a * std::sqrt(2.0))), 0.01);
}

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

}  // namespace
