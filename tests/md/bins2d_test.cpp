// Fields on the 2-D bins over x-y (bins2d.hpp): the binned stress of a uniform
// compressed block equals the box stress of eq. 2.25; the temperature is about each
// bin's own mean velocity.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/core/units.hpp"
#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

using namespace mpmx;
using namespace mpmx::md;

// A periodic, homogeneously strained perfect crystal moving as a whole: every bin holds
// the same atoms (bins a whole number of cells, planes off the bin edges), so each bin's
// stress of eq. 2.25 is the box's, to round-off.
TEST(JetBins, UniformCompressedBlockEqualsBoxStress) {
  const double a = 3.615, ex = -0.08, ey = -0.03;
  Crystal cr = fcc(8, 4, 3, a, ex);
  for (auto& y : cr.atoms.y) y *= 1 + ey;
  cr.box.ly *= 1 + ey;
  for (std::size_t i = 0; i < cr.atoms.size(); ++i) {  // a quarter plane spacing off the edges
    cr.atoms.x[i] += 0.125 * a * (1 + ex);
    cr.atoms.y[i] += 0.125 * a * (1 + ey);
  }
  SystemOptions o;
  o.per_atom = true;
  System s(cr, test::copper(), o);
  Atoms& at = s.edit_atoms();
  for (std::size_t i = 0; i < at.size(); ++i) at.vx[i] = -25.0, at.vy[i] = 3.0, at.vz[i] = 1.0;
  s.refresh();
  const Mat3 box = s.stress();
  ASSERT_LT(box[0], -0.05);  // about -13 GPa... compressed
  BinGrid g;
  g.nx = 4, g.ny = 2;
  g.x0 = 0, g.dx = s.box().lx / 4, g.dy = s.box().ly / 2, g.lz = s.box().lz;
  const BinFields f = bin_fields(s.snapshot(), s.type_mass(), s.per_atom_virial(), g);
  const double scale = std::abs(box[0]);
  for (int b = 0; b < 8; ++b) {
    EXPECT_EQ(f.atoms[b], static_cast<int>(at.size()) / 8);
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(f.stress[b][k], box[k], 1e-12 * scale) << "bin " << b << " k " << k;
    EXPECT_NEAR(f.vx[b], -25.0, 1e-12);
    EXPECT_NEAR(f.temperature[b], 0.0, 1e-9);
    EXPECT_NEAR(f.density_g_cm3(b), 8.93 / ((1 + ex) * (1 + ey)), 0.01);
  }
}

TEST(JetBins, TemperatureAboutTheBinMean) {
  Crystal cr = fcc(4, 4, 4, 3.615);
  SystemOptions o;
  o.per_atom = true;
  System s(cr, test::copper(), o);
  s.thermalize(150.0, 3, 0);  // kinetic temperature exactly 300 K over 3N - 3
  BinGrid g;
  g.nx = 1, g.ny = 1, g.x0 = 0, g.dx = s.box().lx, g.dy = s.box().ly, g.lz = s.box().lz;
  const BinFields f = bin_fields(s.snapshot(), s.type_mass(), s.per_atom_virial(), g);
  EXPECT_NEAR(f.temperature[0], s.temperature(), 1e-9 * s.temperature());
  const Mat3 box = s.stress();
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(f.stress[0][k], box[k], 1e-12 * std::abs(box[0]) + 1e-15);
}
