// The Nose-Hoover chain thermostat and MTK barostat (md/nose_hoover.hpp) on small copper
// boxes: NVT holds its temperature, NPT takes a box squeezed by 2% to zero pressure,
// NPH keeps the enthalpy-like conserved motion bounded, and a run split in two with the
// chains' state carried over continues bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;

namespace {

using Stats = mpmx::test::BlockStats;
constexpr auto stats = mpmx::test::block_stats;

System box(double a, double temperature) {
  System s(fcc(4, 4, 4, a), mpmx::test::copper());
  s.thermalize(temperature, 5, 0);  // starts at twice it
  return s;
}

}  // namespace

TEST(NoseHoover, NvtHoldsItsTemperature) {
  System s = box(3.615, 300);
  NoseHooverOptions o;
  o.temperature = 300, o.t_damp = 0.1;
  NoseHoover nh(o, s);
  s.advance_coupled(2000, 0.001, nh);  // from 600 K to 300 K
  std::vector<double> t;
  for (int k = 0; k < 400; ++k) {
    s.advance_coupled(20, 0.001, nh);
    t.push_back(s.temperature());
  }
  const Stats st = stats(t);
  std::printf("NVT 256 atoms: T = %.1f +- %.1f K (target 300)\n", st.mean, st.sem);
  EXPECT_LT(std::abs(st.mean - 300), 3 * st.sem + 3);
  const double lx = s.box().lx;
  EXPECT_EQ(lx, 4 * 3.615);  // no barostat: the box stays
}

TEST(NoseHoover, NptTakesASqueezedBoxToItsTargetPressure) {
  System s = box(0.98 * 3.615, 300);
  NoseHooverOptions o;
  o.temperature = 300, o.barostat = true, o.t_damp = 0.1, o.p_damp = 1.0;
  NoseHoover nh(o, s);
  const double p0 = -(s.stress_gpa()[0] + s.stress_gpa()[4] + s.stress_gpa()[8]) / 3;
  s.advance_coupled(6000, 0.001, nh);
  std::vector<double> p, a;
  for (int k = 0; k < 500; ++k) {
    s.advance_coupled(20, 0.001, nh);
    const Mat3 g = s.stress_gpa();
    p.push_back(-(g[0] + g[4] + g[8]) / 3);
    a.push_back(s.box().lx / 4);
  }
  const Stats sp = stats(p), sa = stats(a);
  std::printf("NPT 256 atoms from %.1f GPa: P = %.4f +- %.4f GPa, a = %.5f +- %.5f A\n", p0, sp.mean, sp.sem, sa.mean,
              sa.sem);
  EXPECT_GT(p0, 5);
  EXPECT_LT(std::abs(sp.mean), 3 * sp.sem + 0.01);
  // Mishin copper at 300 K: a thermal expansion of about 0.45% over 3.615 A.
  EXPECT_NEAR(sa.mean, 3.632, 0.003);
  EXPECT_EQ(s.box().lx, s.box().ly);  // isotropic
}

TEST(NoseHoover, AnisotropicBarostatMeetsEachAxisTarget) {
  System s = box(3.615, 300);
  NoseHooverOptions o;
  o.temperature = 300, o.barostat = true, o.isotropic = false, o.pressure = {2.0, 0.0, 0.0};
  NoseHoover nh(o, s);
  s.advance_coupled(6000, 0.001, nh);
  std::vector<double> px, py;
  for (int k = 0; k < 500; ++k) {
    s.advance_coupled(20, 0.001, nh);
    px.push_back(-s.stress_gpa()[0]), py.push_back(-s.stress_gpa()[4]);
  }
  const Stats sx = stats(px), sy = stats(py);
  std::printf("NPT aniso: pxx = %.3f +- %.3f (2), pyy = %.3f +- %.3f (0) GPa\n", sx.mean, sx.sem, sy.mean, sy.sem);
  EXPECT_LT(std::abs(sx.mean - 2.0), 3 * sx.sem + 0.02);
  EXPECT_LT(std::abs(sy.mean), 3 * sy.sem + 0.02);
  EXPECT_LT(s.box().lx, s.box().ly);  // squeezed along x only
}

// npt, nph and nphug: the second half resumed from state() alone, about a system other
// than the one it started with (as --resume builds it), goes on to the bit.
TEST(NoseHoover, SplitRunContinuesBitForBit) {
  NoseHooverOptions npt, nph, hug;
  npt.temperature = 300, npt.barostat = true;
  nph = npt, nph.thermostat = false;
  hug = npt, hug.hugoniot = true, hug.isotropic = false, hug.axes = {true, false, false}, hug.pressure = {5, 5, 5};
  for (const NoseHooverOptions& o : {npt, nph, hug}) {
    System a = box(3.615, 300);
    NoseHoover na(o, a);
    a.advance_coupled(150, 0.001, na);
    System b = a;
    NoseHoover nb(o, b.atoms().size(), na.state());
    a.advance_coupled(150, 0.001, na);
    b.advance_coupled(150, 0.001, nb);
    std::vector<double> xa(a.atoms().x), xb(b.atoms().x);
    EXPECT_EQ(mpmx::test::differing_bits(xa, xb), 0u);
    EXPECT_EQ(std::memcmp(&a.box().lx, &b.box().lx, sizeof(double)), 0);
    EXPECT_EQ(na.state(), nb.state());
    EXPECT_EQ(na.e0(), nb.e0());
  }
  EXPECT_THROW(NoseHoover(npt, 256, {1.0, 2.0}), mpmx::InputError);
}
