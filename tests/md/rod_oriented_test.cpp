// The rod of an oriented crystal (md/rod.hpp with [lattice] type and orient): bcc Ta with
// x along [110] (CuTa.eam.alloy) counted in its tiles, its atoms a bond apart at the
// closest, flyer and target parted between planes; a short run through the impact keeps
// the energy as the fcc rod along the cube axes does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mpmx/md/rod.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

#include "md_test_util.hpp"

namespace rod_oriented {

using namespace mpmx;
using namespace mpmx::md;

Potential tantalum() {
  EamSpec spec;
  spec.file = test::kLammpsPotentials + "CuTa.eam.alloy";
  spec.elements = {"Ta"};
  return Potential(spec);
}

// bcc Ta, x [110], y [-110], z [001]: tiles a sqrt 2 x a sqrt 2 x a of 4 atoms.
RodConfig tantalum_rod(double temperature) {
  RodConfig c;
  c.lattice_constant = 3.30253111631;  // the potential's 0 K constant (M6)
  c.lattice.style = particles::LatticeStyle::bcc;
  c.lattice.orient = {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};
  c.target_cells = {10, 2, 3};
  c.flyer_cells = 2;
  c.temperature = temperature;
  c.seed = 7;
  return c;
}

// The largest excursion of the total energy per atom over `steps` after the flyer is sent.
double energy_excursion(const RodConfig& c, const Potential& pot, int steps) {
  RodGeometry g;
  System s = build_rod(c, pot, {}, &g);
  s.release_rigid({5.0, 0.0, 0.0});
  const double n = static_cast<double>(s.atoms().size()), e0 = test::total_energy(s);
  double worst = 0;
  for (int k = 0; k < steps; k += 10) {
    s.advance(10, 0.002);
    worst = std::max(worst, std::abs(test::total_energy(s) - e0) / n);
  }
  return worst;
}

}  // namespace rod_oriented

TEST(RodOriented, BccTantalumAlong110IsBuiltOfItsTilesAtomsABondApart) {
  using namespace rod_oriented;
  const RodConfig c = tantalum_rod(0.0);
  RodGeometry g;
  const System s = build_rod(c, tantalum(), {}, &g);
  const Atoms& a = s.atoms();
  const double a0 = c.lattice_constant, tx = std::sqrt(2.0) * a0;
  ASSERT_EQ(a.size(), 4u * 12 * 2 * 3);
  EXPECT_EQ(g.flyer_atoms, 4 * 2 * 2 * 3);
  EXPECT_NEAR(g.impact_face, 2 * tx, 1e-12);
  EXPECT_NEAR(g.length, 10 * tx, 1e-12);
  EXPECT_NEAR(g.ly, 2 * tx, 1e-12);
  EXPECT_NEAR(g.lz, 3 * a0, 1e-12);
  // The flyer's atoms before the impact face, the target's on it and beyond, the planes
  // across x a half tile apart (the face half way between the flyer's last and the
  // target's first).
  double flyer_last = -1e9, target_first = 1e9;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x = a.x[i] - g.offset[0];
    if (a.id[i] <= g.flyer_atoms) flyer_last = std::max(flyer_last, x);
    else target_first = std::min(target_first, x);
  }
  EXPECT_NEAR(target_first, g.impact_face, 1e-12);
  EXPECT_NEAR(g.impact_face - flyer_last, 0.5 * tx, 1e-12);
  // No two atoms closer than bcc's nearest neighbours, sqrt(3)/2 a, and some that close.
  double closest = 1e9;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      closest = std::min(closest, std::hypot(a.x[i] - a.x[j], a.y[i] - a.y[j], a.z[i] - a.z[j]));
  EXPECT_NEAR(closest, std::sqrt(3.0) / 2.0 * a0, 1e-12);
}

TEST(RodOriented, ShortRunKeepsTheEnergyAsTheFccRodDoes) {
  using namespace rod_oriented;
  RodConfig fcc;
  fcc.lattice_constant = 3.615;
  fcc.target_cells = {8, 3, 3};
  fcc.flyer_cells = 2;
  fcc.temperature = 300.0;
  fcc.seed = 7;
  const double cu = energy_excursion(fcc, test::copper(), 200);
  const double ta = energy_excursion(tantalum_rod(300.0), tantalum(), 200);
  std::printf("rod energy excursion over 200 steps of 2 fs through the impact: fcc Cu %.3g, bcc Ta [110] %.3g "
              "eV/atom\n", cu, ta);
  EXPECT_LT(ta, 1e-4);
  EXPECT_LT(ta, 3.0 * cu + 1e-6);
}
