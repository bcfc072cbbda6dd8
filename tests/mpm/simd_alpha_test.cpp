// ctest-label: unit
// The two vector forms of DDMP's alpha (eq. 3.27) against its exact value, over a cell
// and at its ends, whichever form this build's kernels use (the scalar formula of the
// stencil path is itself within about 3 ulp):
// the series form runs here on the float estimate (12 bits), a harder start than the
// AVX-512 one it serves (14 bits).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "mpmx/mpm/shape/simd.hpp"

namespace {

using namespace mpmx::mpm::shape;

template <class Alpha>
double worst_ulps(Alpha alpha, const std::vector<double>& fs) {
  double worst = 0.0;
  for (std::size_t i = 0; i + simd::kLanes <= fs.size(); i += simd::kLanes) {
    const simd::vdouble f = simd::load(fs.data() + i);
    const simd::vdouble a = alpha(f);
    for (int k = 0; k < simd::kLanes; ++k) {
      // The exact value, to long double: 0.5 q^{3/2}, q = 4 f (1 - f).
      const long double fl = fs[i + k], q = 4.0L * fl * (1.0L - fl);
      const double want = static_cast<double>(0.5L * q * std::sqrt(q));
      const double ulp = std::max(std::nextafter(want, 1.0) - want, 1e-300);
      if (want < 1e-40) {
        EXPECT_LT(std::abs(a[k]), 1e-40) << "f = " << fs[i + k];
        continue;
      }
      worst = std::max(worst, std::abs(a[k] - want) / ulp);
    }
  }
  return worst;
}

std::vector<double> fractions() {
  std::vector<double> fs;
  for (int i = 0; i <= 100000; ++i) fs.push_back(i / 100000.0);
  for (double e = 1e-18; e < 1e-2; e *= 1.7) fs.push_back(e), fs.push_back(1.0 - e);
  fs.push_back(0.0), fs.push_back(std::nextafter(1.0, 0.0)), fs.push_back(0.5);
  while (fs.size() % simd::kLanes) fs.push_back(0.25);
  return fs;
}

TEST(SimdAlpha, SeriesWithinFewUlpOfTheExactValue) {
  const double ulps = worst_ulps([](simd::vdouble f) { return simd::alpha_series(f); }, fractions());
  std::printf("series: worst %.1f ulp over [0, 1)\n", ulps);
  EXPECT_LE(ulps, 6.0);  // measured 5 (SSE2 and AVX2 builds)
}

TEST(SimdAlpha, SquareRootWithinFewUlpOfTheExactValue) {
  const double ulps = worst_ulps([](simd::vdouble f) { return simd::alpha_sqrt(f); }, fractions());
  std::printf("square root: worst %.1f ulp over [0, 1)\n", ulps);
  EXPECT_LE(ulps, 4.0);  // measured 3
}

TEST(SimdAlpha, NoNanFromRoundingPastTheCellEnds) {
  // f a hair outside [0, 1] gives t a hair below zero.
  for (const double f : {-1e-17, 1.0 + 2e-16}) {
    const simd::vdouble v = simd::splat(f);
    const simd::vdouble a = simd::alpha_series(v), b = simd::alpha_sqrt(v);
    for (int k = 0; k < simd::kLanes; ++k) {
      EXPECT_LT(std::abs(a[k]), 1e-40);
      EXPECT_EQ(b[k], 0.0);
    }
  }
}

}  // namespace
