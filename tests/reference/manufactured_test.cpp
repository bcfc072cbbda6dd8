// The manufactured axis-aligned solution (N4): its body force makes u an exact solution
// of rho a = div sigma + rho b with the Hencky stress of the hypoelastic law, checked by
// finite differences in the current configuration; and the observed order of a
// convergence study.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/convergence.hpp"
#include "mpmx/reference/manufactured.hpp"

using namespace mpmx;

namespace {

reference::AxisAligned solution() {
  reference::AxisAligned m;
  m.A = 0.05, m.c = 3.0, m.lambda = 2.0, m.mu = 1.5, m.rho0 = 1.7, m.dim = 2;
  return m;
}

// sigma_aa at material point X (Hencky form of the hypoelastic law).
double sigma(const reference::AxisAligned& m, const double* X, int a, double t) {
  double tr = 0.0;
  for (int b = 0; b < m.dim; ++b) tr += std::log(reference::stretch(m, X[b], t));
  return m.lambda * tr + 2.0 * m.mu * std::log(reference::stretch(m, X[a], t));
}

}  // namespace

TEST(Manufactured, BodyForceBalancesTheMomentumEquation) {
  const auto m = solution();
  for (double t : {0.1, 0.37, 0.8})
    for (double X0 : {0.13, 0.4, 0.71})
      for (double Y0 : {0.05, 0.52}) {
        const double X[2] = {X0, Y0};
        for (int a = 0; a < 2; ++a) {
          const double h = 1e-5;
          // Acceleration of the material point.
          const double acc = (reference::displacement(m, X[a], t + h) - 2.0 * reference::displacement(m, X[a], t) +
                              reference::displacement(m, X[a], t - h)) /
                             (h * h);
          // d sigma_aa / d x_a = (d sigma_aa / d X_a) / F_aa.
          double Xp[2] = {X[0], X[1]}, Xm[2] = {X[0], X[1]};
          Xp[a] += h, Xm[a] -= h;
          const double dsdX = (sigma(m, Xp, a, t) - sigma(m, Xm, a, t)) / (2.0 * h);
          const double F = reference::stretch(m, X[a], t);
          const double J = reference::stretch(m, X[0], t) * reference::stretch(m, X[1], t);
          const double rho = m.rho0 / J;
          const double residual = rho * acc - dsdX / F - rho * reference::body_force(m, X, a, t);
          EXPECT_NEAR(residual, 0.0, 1e-4 * (std::abs(dsdX / F) + std::abs(rho * acc) + 1e-3))
              << "t " << t << " X " << X0 << ", " << Y0 << " axis " << a;
        }
      }
}

TEST(Manufactured, VelocityIsTheTimeDerivativeAndStretchTheGradient) {
  const auto m = solution();
  const double h = 1e-6, X = 0.3, t = 0.45;
  EXPECT_NEAR(reference::velocity(m, X, t),
              (reference::displacement(m, X, t + h) - reference::displacement(m, X, t - h)) / (2 * h), 1e-8);
  EXPECT_NEAR(reference::stretch(m, X, t),
              1.0 + (reference::displacement(m, X + h, t) - reference::displacement(m, X - h, t)) / (2 * h), 1e-8);
}

TEST(Manufactured, RefusesAnAmplitudeThatInvertsTheStretch) {
  auto m = solution();
  m.A = 0.2;  // 2 pi A > 1
  EXPECT_THROW(reference::validate(m), InputError);
  m = solution();
  m.c = -1.0;
  EXPECT_THROW(reference::validate(m), InputError);
  EXPECT_NO_THROW(reference::validate(solution()));
}

TEST(Convergence, ObservedOrderIsTheLeastSquaresSlope) {
  const std::vector<double> h{0.1, 0.05, 0.025};
  EXPECT_NEAR(app::observed_order(h, {3e-2, 7.5e-3, 1.875e-3}), 2.0, 1e-12);
  EXPECT_NEAR(app::observed_order(h, {1e-2, 5e-3, 2.5e-3}), 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(app::observed_order({0.1}, {1e-2})));
  EXPECT_TRUE(std::isnan(app::observed_order(h, {0.0, 0.0, 0.0})));
}
