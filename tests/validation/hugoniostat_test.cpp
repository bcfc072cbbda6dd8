// ctest-label: validation
// The copper Hugoniot from the Hugoniostat (md/nose_hoover.hpp, LAMMPS's fix nphug form):
// a 500-atom Mishin box at 300 K (its NPT lattice constant, so P0 is about 0) held at the
// stress of the experimental fit Us = 3.94 + 1.49 up (rho0 Us up) for up = 1, 2, 2.5
// km/s gives Us within 3% of the fit at the up it reaches; from 10 K at J1's plateau
// (172 GPa) the shock moves into material at rest within 3% of J1's direct-MD front
// (5.21 km/s at s = 0.1, docs/jet.md). LAMMPS's fix nphug on the same box:
// npt_lammps_crosscheck_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../md/hugoniostat_run.hpp"

using mpmx::test::hugoniostat;
using mpmx::test::Shocked;

TEST(Hugoniostat, CopperHugoniotMeetsExperimentAndDirectMd) {
  const double rho0 = 8.81;  // g/cm^3, Mishin copper at 300 K
  for (double up : {1.0, 2.0, 2.5}) {
    const double us_fit = 3.94 + 1.49 * up;
    const Shocked r = hugoniostat(3.63195, 300, rho0 * us_fit * up);
    const double at_up = 3.94 + 1.49 * r.up;
    std::printf("Hugoniostat 300 K, %.1f GPa: V/V0 %.4f, T %.0f K, up %.3f, Us %.3f km/s (fit there %.3f: %+.2f%%)\n",
                r.p, r.ratio.mean, r.t.mean, r.up, r.us, at_up, 100 * (r.us / at_up - 1));
    EXPECT_NEAR(r.us, at_up, 0.03 * at_up);
  }
  const Shocked j1 = hugoniostat(3.6155, 10, 172);
  const double front = j1.us - j1.up;  // the lab speed of J1's front: into material at rest
  std::printf("Hugoniostat 10 K, 172 GPa: up %.3f, Us %.3f, front %.3f km/s (J1 5.21)\n", j1.up, j1.us, front);
  EXPECT_NEAR(front, 5.21, 0.03 * 5.21);
}
