// ctest-label: unit
// md_closure's `deformation`: a box compressed at a shock front's rate by the seed's
// boundary scheme is shocked from its faces (its images close on it at L x its length),
// while the affine scheme compresses it near the isentrope. A 108-atom box at 10 K to
// J = 0.8 in 0.04 ps (5.6e12 /s).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "mpmx/mpm/points.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "multiscale/ms_test_util.hpp"

using namespace mpmx;

namespace {

// The box's temperature (K) and sigma_xx (GPa) after the compression.
std::pair<double, double> compressed(md::Deformation how) {
  auto md = test::closure_config(test::tiny_bar(1, 3, 2, 10.0));
  md.threads = 1;
  md.deformation = how;
  multiscale::MdClosure<1> m(md);
  mpm::Particles<1> p;
  p.resize(1);
  p.mass[0] = p.volume[0] = 1.0;
  m.initialize(mpm::points(p));
  p.grad_v[0] = {std::log(0.8) / 0.04};  // 1/ps
  for (int k = 0; k < 2; ++k) m.update_stress(mpm::points(p), 0.02);
  double T = 0.0;
  for (const auto& f : m.point_fields(mpm::points(p)))
    if (f.name == "temperature") T = f.values[0];
  return {T, p.stress[0][0]};
}

}  // namespace

TEST(MdClosureAffine, AffineCompressionStaysNearTheIsentropeWhereTheBoundarySchemeShocksTheBox) {
  const auto [Tb, sb] = compressed(md::Deformation::boundary);
  const auto [Ta, sa] = compressed(md::Deformation::affine);
  // The boundary scheme's faces close at 5.6 /ps x 1.08 nm = 6 km/s: 10,700 K, against 17 K.
  EXPECT_GT(Tb, 5000.0);
  EXPECT_LT(Ta, 100.0);
  // Both compress (-54 GPa affine); the shocked box's thermal pressure more than doubles
  // it (-127 GPa).
  EXPECT_LT(sa, -40.0);
  EXPECT_GT(sa, -70.0);
  EXPECT_LT(sb, 1.8 * sa);
}
