// Rigid groups and the Berendsen thermostat (seed 004 sec. 4.1: the rigid flyer at
// 5 Angstrom/ps, the tensile grips at 2.169 Angstrom/ps, 298 K Berendsen equilibration):
// a rigid group's particles move exactly at its velocity whatever the forces; the force
// on it is the sum of the pair forces; the thermostat brings both the kinetic and the
// internal (DPDE) temperature to its target.
#include <gtest/gtest.h>

#include <cmath>

#include "dpd_test_util.hpp"
#include "mpmx/core/units.hpp"

namespace {

using namespace mpmx;

dpd::DpdParams dpde() {
  dpd::DpdParams par;
  par.energy_conserving = true;
  par.gamma = test::kSeedGamma;
  par.cutoff = 12.0;
  par.heat_capacity = test::kCuMesoCv;
  par.seed = 3;
  return par;
}

TEST(DpdRigid, FlyerMovesAtItsVelocityAndPushesTheTarget) {
  // Target 8 x 4 x 4 cells (open along x); a rigid flyer of 2 cells starting 3 Angstrom
  // left of it at 5 Angstrom/ps along +x.
  const double a = test::kCoarseLattice;
  dpd::Particles target = dpd::fcc_block({8, 4, 4}, a, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  dpd::Particles flyer = dpd::fcc_block({2, 4, 4}, a, {-2 * a - 3.0 + 0.25 * a, 0, 0}, test::kCuMesoMass, 0, 10000);
  for (auto& g : flyer.group) g = 0;
  dpd::Particles all = target;
  dpd::append(all, flyer);
  for (auto& u : all.u) u = test::kCuMesoCv * 298;
  dpd::Domain d = test::cube(4 * a, {false, true, true});
  d.box.lx = 8 * a;
  dpd::System s(all, d, test::cu_meso_morse(12.0), dpde(), {.skin = 1.0}, {{"flyer", {5.0, 0.0, 0.0}}});
  const dpd::Particles p0 = s.particles();
  s.advance(400, 0.005);  // 2 ps: 10 Angstrom of flyer travel
  const dpd::Particles& p = s.particles();
  double target_px = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.group[i] == 0) {
      EXPECT_EQ(p.vx[i], 5.0);
      EXPECT_EQ(p.vy[i], 0.0);
    } else {
      target_px += p.mass[i] * p.vx[i];
    }
  }
  // Displacement of one flyer particle (by id): exactly 5 A/ps x 2 ps to round-off.
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == 10001)
      for (std::size_t k = 0; k < p0.size(); ++k)
        if (p0.id[k] == 10001) {
          EXPECT_NEAR(p.x[i] - p0.x[k], 10.0, 1e-9);
          EXPECT_NEAR(d.wrap(1, p.y[i]) - d.wrap(1, p0.y[k]), 0.0, 1e-9);
        }
  EXPECT_GT(target_px, 1000.0) << "the flyer pushed the target along +x";
  EXPECT_LT(s.group_force(0)[0], 0.0) << "the target pushes back on the flyer";
}

TEST(DpdRigid, GripsPullAtTheirVelocityAndFeelTheRod) {
  // A rod along x with 2-cell grips at both ends pulled apart at 2.169 Angstrom/ps.
  const double a = test::kCoarseLattice;
  dpd::Particles rod = dpd::fcc_block({12, 3, 3}, a, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  for (std::size_t i = 0; i < rod.size(); ++i) {
    if (rod.x[i] < 2 * a - 0.1) rod.group[i] = 0;
    if (rod.x[i] > 10 * a - 0.1) rod.group[i] = 1;
  }
  for (auto& u : rod.u) u = test::kCuMesoCv * 298;
  dpd::Domain d = test::cube(3 * a, {false, false, false});
  d.box.lx = 12 * a;
  dpd::System s(rod, d, test::cu_meso_morse(12.0), dpde(), {.skin = 1.0},
                {{"left", {-2.169, 0, 0}}, {"right", {2.169, 0, 0}}});
  s.advance(600, 0.005);  // 3 ps: strain 2 x 2.169 x 3 / 86.8 = 15%
  const dpd::Particles& p = s.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.group[i] == 0) {
      EXPECT_EQ(p.vx[i], -2.169);
    } else if (p.group[i] == 1) {
      EXPECT_EQ(p.vx[i], 2.169);
    }
  }
  // The stretched rod pulls the grips inwards with equal and opposite forces.
  const auto fl = s.group_force(0), fr = s.group_force(1);
  EXPECT_GT(fl[0], 0.0);
  EXPECT_LT(fr[0], 0.0);
  EXPECT_NEAR(fl[0], -fr[0], 0.3 * std::abs(fl[0]));
}

TEST(DpdBerendsen, BringsKineticAndInternalTemperaturesToTheTarget) {
  dpd::Particles p = dpd::fcc_block({5, 5, 5}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  dpd::maxwell_velocities(p, 50.0, 9);
  for (auto& u : p.u) u = test::kCuMesoCv * 100.0;
  dpd::System s(p, test::cube(5 * test::kCoarseLattice), test::cu_meso_morse(12.0), dpde(), {.skin = 1.0});
  const dpd::Berendsen b{.temperature = 298.0, .tau = 0.5};
  s.advance(2000, 0.005, &b);  // 10 ps = 20 tau
  double t = 0;
  for (int k = 0; k < 40; ++k) {
    s.advance(10, 0.005, &b);
    t += s.temperature() / 40;
  }
  EXPECT_NEAR(t, 298.0, 0.02 * 298.0);
  EXPECT_NEAR(s.internal_temperature(), 298.0, 0.5);
}

}  // namespace
