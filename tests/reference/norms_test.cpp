// Relative l1 / l2 error norms.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/norms.hpp"

using mpmx::InputError;
namespace ref = mpmx::reference;

TEST(Norms, HandComputedValues) {
  // Density around rho0 = 1: reference disturbances 0.1, -0.2, 0.3, errors 0.01, 0.02, -0.03.
  const std::vector<double> r{1.1, 0.8, 1.3}, u{1.11, 0.82, 1.27}, w{1.0, 2.0, 0.5};
  const ref::ErrorNorms n = ref::relative_error_norms(u, r, w, 1.0);
  // l1 = (0.01 + 0.04 + 0.015) / (0.1 + 0.4 + 0.15) = 0.065 / 0.65
  EXPECT_NEAR(n.l1, 0.1, 1e-14);
  // l2 = sqrt((1e-4 + 8e-4 + 4.5e-4) / (0.01 + 0.08 + 0.045)) = sqrt(0.00135 / 0.135)
  EXPECT_NEAR(n.l2, 0.1, 1e-14);
  // Same numbers, baseline 0: the denominator is now the whole field, not the wave.
  const ref::ErrorNorms n0 = ref::relative_error_norms(u, r, w, 0.0);
  EXPECT_NEAR(n0.l1, 0.065 / (1.1 + 1.6 + 0.65), 1e-14);
  EXPECT_NEAR(n0.l2, std::sqrt(0.00135 / (1.21 + 1.28 + 0.845)), 1e-14);
}

TEST(Norms, ExactMatchIsZeroAndWeightsMatter) {
  const std::vector<double> r{0.0, 1.0, -1.0}, w{1.0, 1.0, 1.0}, w2{1.0, 3.0, 1.0};
  const ref::ErrorNorms z = ref::relative_error_norms(r, r, w, 0.0);
  EXPECT_EQ(z.l1, 0.0);
  EXPECT_EQ(z.l2, 0.0);
  const std::vector<double> u{0.0, 1.5, -1.0};
  EXPECT_NEAR(ref::relative_error_norms(u, r, w, 0.0).l1, 0.25, 1e-15);
  EXPECT_NEAR(ref::relative_error_norms(u, r, w2, 0.0).l1, 1.5 / 4.0, 1e-15);
}

TEST(Norms, RejectsBadInput) {
  const std::vector<double> a{1.0, 2.0}, b{1.0}, neg{1.0, -1.0}, flat{3.0, 3.0}, bad{1.0, NAN};
  EXPECT_THROW(ref::relative_error_norms(a, b, a, 0.0), InputError);
  EXPECT_THROW(ref::relative_error_norms({}, {}, {}, 0.0), InputError);
  EXPECT_THROW(ref::relative_error_norms(a, a, neg, 0.0), InputError);
  EXPECT_THROW(ref::relative_error_norms(a, flat, a, 3.0), InputError);  // no disturbance
  EXPECT_THROW(ref::relative_error_norms(bad, a, a, 0.0), InputError);
}
