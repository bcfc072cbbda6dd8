// ctest-label: validation
// M5 (section 5.2): under any velocity gradient, made upper triangular by eq. 5.20, the
// rectangular fundamental box keeps every atom exactly once (figs. 5.2-5.3); under pure
// stretch at 0 K the periodic lattice stays a perfect lattice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

#include "../md/md_test_util.hpp"

using namespace mpmx::md;

namespace {
using mpmx::test::copper;

// Smallest distance between two atoms of the periodic system (brute force over images).
double min_separation(const Atoms& a, const Box& b) {
  double best = 1e300;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) {
      double d[3] = {a.x[i] - a.x[j], a.y[i] - a.y[j], a.z[i] - a.z[j]};
      for (int n3 = -1; n3 <= 1; ++n3)
        for (int n2 = -1; n2 <= 1; ++n2)
          for (int n1 = -1; n1 <= 1; ++n1) {
            const Vec3 s = b.shift(n1, n2, n3);
            const double dx = d[0] + s[0], dy = d[1] + s[1], dz = d[2] + s[2];
            best = std::min(best, dx * dx + dy * dy + dz * dz);
          }
    }
  return std::sqrt(best);
}
}  // namespace

TEST(M5, UpperTriangularTransformOfEq520) {
  const Mat3 g{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
  const Mat3 u = upper_triangular(g);
  const Mat3 want{0.1, 0.6, 1.0, 0.0, 0.5, 1.4, 0.0, 0.0, 0.9};
  for (int k = 0; k < 9; ++k) EXPECT_DOUBLE_EQ(u[k], want[k]) << k;
  EXPECT_TRUE(is_upper_triangular(u));
  EXPECT_FALSE(is_upper_triangular(g));
}

TEST(M5, AtomCountConstantUnderArbitraryGradient) {
  System s(fcc(4, 4, 4, 3.615), copper());
  s.thermalize(300, 7, 0);
  const std::size_t n = s.atoms().size();
  // Shear, stretch and rotation together (lower triangle present): 2.5 ps at up to
  // 0.25/ps gives tilts beyond half the box, so the images are also re-based.
  const Mat3 g{0.02, 0.25, 0.05, 0.1, -0.02, 0.1, 0.05, -0.15, 0.01};
  const Mat3 u = upper_triangular(g);
  const double v0 = s.box().volume();
  double growth = 1.0;
  for (int chunk = 0; chunk < 10; ++chunk) {
    s.advance(250, g, 0.001);
    const Atoms a = s.snapshot();
    ASSERT_EQ(a.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      ASSERT_TRUE(a.x[i] >= 0 && a.x[i] < s.box().lx) << a.x[i];
      ASSERT_TRUE(a.y[i] >= 0 && a.y[i] < s.box().ly) << a.y[i];
      ASSERT_TRUE(a.z[i] >= 0 && a.z[i] < s.box().lz) << a.z[i];
    }
    // No atom and its own image both inside: all separations physical.
    EXPECT_GT(min_separation(a, s.box()), 1.5);
  }
  for (int k = 0; k < 2500; ++k) growth *= (1 + 0.001 * u[0]) * (1 + 0.001 * u[4]) * (1 + 0.001 * u[8]);
  EXPECT_NEAR(s.box().volume() / v0, growth, 1e-12);  // eq. 5.7 on each length
  EXPECT_LE(std::abs(s.box().xy), 0.5 * s.box().lx + 1e-12);
  EXPECT_GT(s.neighbor_builds(), 1);
}

TEST(M5, PureStretchKeepsAPerfectLattice) {
  for (Deformation mode : {Deformation::affine, Deformation::boundary}) {
    SystemOptions o;
    o.deformation = mode;
    System s(fcc(4, 4, 4, 3.615), copper(), o);
    const Atoms a0 = s.atoms();
    const Box b0 = s.box();
    const Mat3 g{2e-3, 0, 0, 0, -1e-3, 0, 0, 0, 5e-4};  // 1/ps
    if (mode == Deformation::boundary) s.add_streaming_velocity(g);  // affine: v is peculiar
    s.advance(2000, g, 0.001);
    // Compare with the affine image of the initial lattice (per atom id), modulo the box.
    const Atoms a = s.snapshot();
    const Box& b = s.box();
    const double sx = b.lx / b0.lx, sy = b.ly / b0.ly, sz = b.lz / b0.lz;
    double worst = 0, fmax = 0, t[3] = {0, 0, 0};
    for (std::size_t i = 0; i < a.size(); ++i) {
      std::size_t j = 0;
      while (a0.id[j] != a.id[i]) ++j;
      double d[3] = {a.x[i] - a0.x[j] * sx, a.y[i] - a0.y[j] * sy, a.z[i] - a0.z[j] * sz};
      // A rigid translation of the whole lattice is allowed: measure from atom 0's offset.
      if (i == 0) t[0] = d[0], t[1] = d[1], t[2] = d[2];
      for (int c = 0; c < 3; ++c) d[c] -= t[c];
      d[0] -= std::round(d[0] / b.lx) * b.lx;
      d[1] -= std::round(d[1] / b.ly) * b.ly;
      d[2] -= std::round(d[2] / b.lz) * b.lz;
      worst = std::max({worst, std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
      fmax = std::max({fmax, std::abs(a.fx[i]), std::abs(a.fy[i]), std::abs(a.fz[i])});
    }
    std::printf("M5 %s: lx strain %.4f, max deviation from perfect lattice %.3g A, max force %.3g eV/A\n",
                mode == Deformation::affine ? "affine" : "boundary", sx - 1, worst, fmax);
    if (mode == Deformation::affine) {
      EXPECT_LT(worst, 1e-9);
      EXPECT_LT(fmax, 1e-9);
    } else {
      EXPECT_LT(worst, 1e-6);  // streaming atoms lag the exponential box growth by O((g t)^2)
    }
    // Uniform stretch: shear stresses vanish.
    const Mat3 sig = s.stress_gpa();
    EXPECT_NEAR(sig[1], 0.0, 1e-6);
    EXPECT_NEAR(sig[2], 0.0, 1e-6);
    EXPECT_NEAR(sig[5], 0.0, 1e-6);
  }
}
