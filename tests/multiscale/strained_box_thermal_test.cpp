// ctest-label: slow
// ctest-cost: 40000
// The MD crystal's elastic constants at 298 K from strained boxes (multiscale/
// strained_box.hpp), Sutton-Chen Cu of D0 at its 298 K zero-pressure lattice constant:
// 500 and 4,000 atoms give the same C11 and C12 within their noise (no box-size term at
// this size), within 5% of the static lattice's at the same density.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/md/potential/sutton_chen.hpp"
#include "mpmx/multiscale/strained_box.hpp"

using namespace mpmx;

TEST(StrainedBoxThermal, SuttonChenConstantsAt298KDoNotDependOnTheBoxSize) {
  md::SuttonChenSpec sc;  // D0's MD potential
  sc.epsilon = 1.2382e-2, sc.a = 3.61, sc.c = 39.432, sc.n = 9, sc.m = 6, sc.cutoff = 9.0, sc.mass = 63.546;
  const md::Potential pot(sc);
  const double a = 3.61 / std::cbrt(0.9742);  // D0's zero-pressure density at 298 K
  multiscale::StrainedBoxOptions o;
  o.temperature = 298, o.equilibrate_steps = 2000, o.sample_steps = 4000, o.threads = 2;
  o.cells = 5;
  const auto small = multiscale::md_strained_constants(pot, a, o);
  o.cells = 10;  // 8 times the atoms: as little noise from fewer samples (the strained boxes
  o.sample_steps = 1500;  // still settle 2 ps: 1 ps left C11 2 GPa high)
  const auto large = multiscale::md_strained_constants(pot, a, o);
  multiscale::StrainedBoxOptions s;
  s.cells = 5;
  const auto cold = multiscale::md_strained_constants(pot, a, s);
  std::printf("C11 %.2f +- %.2f / %.2f +- %.2f (0 K %.2f), C12 %.2f +- %.2f / %.2f +- %.2f (0 K %.2f) GPa, "
              "P %.3f / %.3f GPa\n",
              small.c11, small.c11_error, large.c11, large.c11_error, cold.c11, small.c12, small.c12_error, large.c12,
              large.c12_error, cold.c12, small.pressure, large.pressure);
  // Four standard errors of the difference, and at least 2% (block errors of a short run
  // understate the noise).
  const double t11 = std::max(4 * std::hypot(small.c11_error, large.c11_error), 0.02 * large.c11);
  const double t12 = std::max(4 * std::hypot(small.c12_error, large.c12_error), 0.02 * large.c12);
  EXPECT_NEAR(small.c11, large.c11, t11);
  EXPECT_NEAR(small.c12, large.c12, t12);
  // At a fixed density the thermal constants need not lie below the static ones.
  EXPECT_NEAR(large.c11, cold.c11, 0.05 * cold.c11);
  EXPECT_NEAR(large.c12, cold.c12, 0.05 * cold.c12);
  EXPECT_LT(std::abs(large.pressure), 0.5);  // the zero-pressure density is D0's
}
