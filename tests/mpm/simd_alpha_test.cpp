// ctest-label: unit
// The vector form of DDMP's alpha (eq. 3.27) against its exact value, over a cell and at
// its ends, on every vector path this machine has (the scalar formula of the stencil path
// is itself within about 3 ulp), and the same on every path.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the kernels' paths
// clang-format on

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "../tests/mpm/simd_alpha_test.cpp"  // from src/, the include path
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "mpmx/mpm/fused1d/simd.hpp"

// What the test needs of each path, over the whole vector of the kernels (DFull).
HWY_BEFORE_NAMESPACE();
namespace mpmx::mpm::shape::HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using D = simd::DFull;

// Writes alpha of fs into out (size a multiple of the lanes).
void alpha_of(const double* fs, std::size_t n, double* out) {
  const D d;
  for (std::size_t i = 0; i < n; i += simd::kLanes<D>) hn::StoreU(simd::alpha(hn::LoadU(d, fs + i)), d, out + i);
}

std::size_t lanes() { return simd::kLanes<D>; }

}  // namespace
}  // namespace mpmx::mpm::shape::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::mpm::shape {
namespace {

HWY_EXPORT(alpha_of);
HWY_EXPORT(lanes);

// Runs body(name) once per path of this file that the machine has, dispatch forced to it.
template <class Body>
void on_every_path(Body body) {
  for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    body(hwy::TargetName(target));
  }
  hwy::SetSupportedTargetsForTest(0);
}

std::vector<double> fractions() {
  std::vector<double> fs;
  for (int i = 0; i <= 100000; ++i) fs.push_back(i / 100000.0);
  for (double e = 1e-18; e < 1e-2; e *= 1.7) fs.push_back(e), fs.push_back(1.0 - e);
  fs.push_back(0.0), fs.push_back(std::nextafter(1.0, 0.0)), fs.push_back(0.5);
  while (fs.size() % 16) fs.push_back(0.25);  // whole vectors of any width
  return fs;
}

// alpha on the path dispatch takes now, and its worst error over fractions() in ulp.
double worst_ulps(const char* path, std::vector<double>& a) {
  const std::vector<double> fs = fractions();
  a.resize(fs.size());
  HWY_DYNAMIC_DISPATCH(alpha_of)(fs.data(), fs.size(), a.data());
  double worst = 0.0;
  for (std::size_t i = 0; i < fs.size(); ++i) {
    // The exact value, to long double: 0.5 q^{3/2}, q = 4 f (1 - f).
    const long double fl = fs[i], q = 4.0L * fl * (1.0L - fl);
    const double want = static_cast<double>(0.5L * q * std::sqrt(q));
    const double ulp = std::max(std::nextafter(want, 1.0) - want, 1e-300);
    if (want < 1e-40) {
      EXPECT_LT(std::abs(a[i]), 1e-40) << path << ": f = " << fs[i];
      continue;
    }
    worst = std::max(worst, std::abs(a[i] - want) / ulp);
  }
  return worst;
}

TEST(SimdAlpha, EveryPathOfTheMachineTested) {
  std::size_t paths = 0;
  on_every_path([&](const char* path) {
    ++paths;
    std::printf("%s: %zu lanes\n", path, HWY_DYNAMIC_DISPATCH(lanes)());
  });
  EXPECT_GE(paths, 1u);
}

TEST(SimdAlpha, WithinFewUlpOfTheExactValueAndTheSameOnEveryPath) {
  std::vector<double> first;
  on_every_path([&](const char* path) {
    std::vector<double> a;
    const double ulps = worst_ulps(path, a);
    std::printf("%s: worst %.1f ulp over [0, 1)\n", path, ulps);
    EXPECT_LE(ulps, 4.0) << path;  // measured 3
    if (first.empty()) first = a;
    EXPECT_TRUE(a == first) << path << " differs from the first path";
  });
}

TEST(SimdAlpha, NoNanFromRoundingPastTheCellEnds) {
  // f a hair outside [0, 1] gives t a hair below zero.
  on_every_path([](const char* path) {
    for (const double f : {-1e-17, 1.0 + 2e-16}) {
      const std::vector<double> fs(16, f);
      std::vector<double> a(16);
      HWY_DYNAMIC_DISPATCH(alpha_of)(fs.data(), fs.size(), a.data());
      for (const double ak : a) EXPECT_EQ(ak, 0.0) << path;
    }
  });
}

}  // namespace
}  // namespace mpmx::mpm::shape
#endif  // HWY_ONCE
