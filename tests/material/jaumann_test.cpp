// ctest-label: unit
// The Jaumann rate and its Hughes-Winget update (material/jaumann.hpp): the rotation is
// orthogonal and exact for no spin; rigid rotation of a disk (N7) leaves no stress and
// keeps a pre-stress's invariants; pure shear and simple shear give the known
// hypoelastic responses; the law's total form equals the incremental update.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/material/jaumann.hpp"
#include "point_set.hpp"

namespace mpmx::material {
namespace {

using test::kCopperCubic;
using test::PointSet;
using Eigen::Matrix2d;
using Eigen::Matrix3d;
constexpr double pi = std::numbers::pi;

// Isotropic constants as a cubic crystal: E = 1000, nu = 0.3.
const double E = 1000.0, nu = 0.3;
const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
const CubicConstants iso{lam + 2 * mu, lam, mu};

Matrix3d skew_of(const Eigen::Vector3d& w) {  // [w]x: [w]x v = w x v
  Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

Matrix3d random_symmetric(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Matrix3d m;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) m(a, b) = u(rng);
  return scale * 0.5 * (m + m.transpose());
}

TEST(HughesWinget, OrthogonalAndEqualToTheCayleyTransform) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d w(u(rng), u(rng), u(rng));
    const double dt = 0.1 * std::abs(u(rng));
    const Matrix3d W = skew_of(w);
    const Matrix3d R = jaumann::hughes_winget<3>(W, dt);
    const Matrix3d I = Matrix3d::Identity();
    const Matrix3d cayley = (I - 0.5 * dt * W).inverse() * (I + 0.5 * dt * W);
    EXPECT_LT((R - cayley).norm(), 1e-14);
    EXPECT_LT((R.transpose() * R - I).norm(), 2e-15);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
    // R turns about the spin axis by 2 atan(|w| dt / 2).
    const Eigen::AngleAxisd aa(R);
    EXPECT_NEAR(aa.angle(), 2 * std::atan(0.5 * w.norm() * dt), 1e-13);
    EXPECT_LT((aa.axis() - w.normalized()).norm(), 1e-11);
  }
  // In 2-D the rotation by 2 atan(w dt / 2); no spin gives the identity exactly.
  Matrix2d W2;
  W2 << 0, -0.7, 0.7, 0;
  const Matrix2d R2 = jaumann::hughes_winget<2>(W2, 0.3);
  EXPECT_LT((R2 - test::rotation2(2 * std::atan(0.5 * 0.7 * 0.3))).norm(), 1e-15);
  EXPECT_EQ(jaumann::hughes_winget<3>(Matrix3d::Zero(), 0.5), Matrix3d::Identity());
  EXPECT_EQ(jaumann::hughes_winget<1>(Eigen::Matrix<double, 1, 1>::Zero(), 0.5)(0, 0), 1.0);
}

TEST(Jaumann, RotationTermsVanishForCoaxialStress) {
  // W sigma - sigma W is zero for an isotropic stress; for a symmetric one it is
  // symmetric and traceless.
  const Matrix3d W = skew_of({0.3, -0.2, 0.5});
  EXPECT_EQ(jaumann::rotation_terms<3>(W, 4.0 * Matrix3d::Identity()).norm(), 0.0);
  Matrix3d S;
  S << 1, 2, 0, 2, -1, 0.5, 0, 0.5, 3;
  const Matrix3d J = jaumann::rotation_terms<3>(W, S);
  EXPECT_LT((J - J.transpose()).norm(), 1e-15);  // symmetric: the rate of a symmetric tensor
  EXPECT_NEAR(J.trace(), 0.0, 1e-15);            // the trace (pressure) does not turn
}

// N7: a disk of radius R spinning rigidly at omega for one revolution, dt = T / 1000.
struct Disk {
  static constexpr double R = 1.0, rho = 1.0, omega = 2 * pi;  // T = 1
  static constexpr int steps = 1000;
  static constexpr double dt = 1.0 / steps;
  PointSet<2> pts;
  Disk() : pts(count(), rho, 0.01, 0.1) {}
  static std::size_t count() {
    std::size_t n = 0;
    for (int i = -10; i <= 10; ++i)
      for (int j = -10; j <= 10; ++j) n += (0.1 * i) * (0.1 * i) + (0.1 * j) * (0.1 * j) <= R * R;
    return n;
  }
  // Rigid rotation v = omega e_z x r: L_xy = -omega, L_yx = omega at every point.
  void spin() {
    Matrix2d L;
    L << 0, -omega, omega, 0;
    pts.set_grad_v(L);
  }
};

double deviator_norm(const Matrix3d& s) { return jaumann::deviator(s).norm(); }

TEST(Jaumann, RigidRotationOfAStressFreeDiskLeavesNoStress) {
  Disk d;
  d.spin();
  CubicElastic<2> law(iso);
  auto p = d.pts.view();
  law.initialize(p);
  for (int k = 0; k < Disk::steps; ++k) law.update_stress(p, Disk::dt);
  double worst = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) worst = std::max(worst, d.pts.stress(q).cwiseAbs().maxCoeff());
  const double scale = Disk::rho * std::pow(Disk::omega * Disk::R, 2);
  EXPECT_LT(worst, 1e-8 * scale) << "largest stress " << worst;
}

TEST(Jaumann, RigidRotationKeepsAPrestressedDisksInvariants) {
  Disk d;
  CubicElastic<2> law(iso);
  auto p = d.pts.view();
  std::size_t q = 0;
  for (int i = -10; i <= 10; ++i)
    for (int j = -10; j <= 10; ++j) {
      const double x = 0.1 * i, y = 0.1 * j;
      if (x * x + y * y > 1.0) continue;
      Matrix2d e;
      e << 1e-3 * (1 + x), 4e-4 * (y - x), 4e-4 * (y - x), -5e-4 * (1 - y);
      d.pts.set_strain(q++, e);
    }
  law.initialize(p);
  std::vector<Matrix2d> s0(p.size());
  std::vector<double> dev0(p.size());
  auto full = [&](std::size_t i) {  // the 3x3 stress with plane strain's sigma_zz
    Matrix3d s = jaumann::embed<2>(Matrix2d(d.pts.stress(i)));
    s(2, 2) = law.out_of_plane_stress(p, i);
    return s;
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    s0[i] = d.pts.stress(i);
    dev0[i] = deviator_norm(full(i));
  }
  d.spin();
  for (int k = 0; k < Disk::steps; ++k) law.update_stress(p, Disk::dt);
  // Two half-step Hughes-Winget rotations turn by 4 atan(omega dt / 4) per step:
  // (omega dt)^3 / 48 short of omega dt, 5.17e-6 rad in one revolution.
  const double turned = Disk::steps * 4 * std::atan(0.25 * Disk::omega * Disk::dt);
  EXPECT_NEAR(2 * pi - turned, 5.167e-6, 0.002e-6);
  const Matrix2d Rt = test::rotation2(turned);
  double worst_invariant = 0.0, worst_rotation = 0.0, worst_return = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double ref = s0[i].norm();
    worst_invariant = std::max(worst_invariant, std::abs(deviator_norm(full(i)) - dev0[i]) / dev0[i]);
    worst_rotation = std::max(worst_rotation, (d.pts.stress(i) - Rt * s0[i] * Rt.transpose()).norm() / ref);
    worst_return = std::max(worst_return, (d.pts.stress(i) - s0[i]).norm() / ref);
  }
  EXPECT_LT(worst_invariant, 1e-11) << "norm of the deviator kept to " << worst_invariant;
  EXPECT_LT(worst_rotation, 1e-11) << "stress turned by the predicted angle to " << worst_rotation;
  EXPECT_LT(worst_return, 1e-4) << "back to the initial stress after a revolution: " << worst_return;

  // The same rotation terms by forward Euler inflate the stress: the test can fail.
  Matrix2d W;
  W << 0, -Disk::omega, Disk::omega, 0;
  Matrix2d s = s0[0];
  for (int k = 0; k < Disk::steps; ++k) s += Disk::dt * jaumann::rotation_terms<2>(W, s);
  EXPECT_GT(s.norm() / s0[0].norm() - 1.0, 0.01);
}

TEST(Jaumann, RigidRotationIn3DAboutAnOddAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  const double omega = 2 * pi, dt = 1e-3;
  PointSet<3> pts(4);
  std::mt19937_64 rng(3);
  for (std::size_t q = 0; q < pts.n; ++q) pts.set_strain(q, random_symmetric(rng, 1e-3));
  CubicElastic<3> law(kCopperCubic);  // anisotropic: the crystal axes turn with the point
  auto p = pts.view();
  law.initialize(p);
  std::vector<Matrix3d> s0(pts.n);
  for (std::size_t q = 0; q < pts.n; ++q) s0[q] = pts.stress(q);
  pts.set_grad_v(omega * skew_of(axis));
  for (int k = 0; k < 1000; ++k) law.update_stress(p, dt);
  const Matrix3d Rt = test::rotation3(1000 * 4 * std::atan(0.25 * omega * dt), axis);
  for (std::size_t q = 0; q < pts.n; ++q) {
    const Matrix3d s = pts.stress(q);
    EXPECT_NEAR(deviator_norm(s), deviator_norm(s0[q]), 1e-11 * s0[q].norm());
    EXPECT_NEAR(s.trace(), s0[q].trace(), 1e-11 * s0[q].norm());
    EXPECT_LT((s - Rt * s0[q] * Rt.transpose()).norm(), 1e-11 * s0[q].norm());
    EXPECT_LT((law.axes(q) - Rt).norm(), 1e-11);
  }
}

TEST(Jaumann, PureShearRateGivesTwoMuTimesTheShearStrain) {
  // D = [[0, g], [g, 0]], W = 0: sigma_xy = 2 mu g t, no normal stress.
  PointSet<2> pts(1);
  CubicElastic<2> law(iso);
  auto p = pts.view();
  law.initialize(p);
  const double g = 0.5, dt = 1e-4;
  Matrix2d L;
  L << 0, g, g, 0;
  pts.set_grad_v(L);
  for (int k = 0; k < 100; ++k) law.update_stress(p, dt);
  const double t = 100 * dt;
  EXPECT_NEAR(pts.stress(0)(0, 1), 2 * mu * g * t, 1e-12 * mu * g * t);
  EXPECT_NEAR(pts.stress(0)(1, 0), 2 * mu * g * t, 1e-12 * mu * g * t);
  EXPECT_EQ(pts.stress(0)(0, 0), 0.0);
  EXPECT_EQ(pts.stress(0)(1, 1), 0.0);
}

TEST(Jaumann, SimpleShearFollowsTheJaumannSolution) {
  // L = [[0, gdot], [0, 0]]: the Jaumann hypoelastic solution (Dienes 1979) is
  // sigma_xy = mu sin(gamma), sigma_xx = -sigma_yy = mu (1 - cos(gamma)); to first order
  // in gamma, sigma_xy = mu gamma = 2 mu eps_xy and no normal stress.
  for (const double gamma_end : {0.01, 1.0}) {
    PointSet<2> pts(1);
    CubicElastic<2> law(iso);
    auto p = pts.view();
    law.initialize(p);
    const int steps = 4000;
    const double dt = gamma_end / steps;  // gdot = 1
    Matrix2d L;
    L << 0, 1, 0, 0;
    pts.set_grad_v(L);
    for (int k = 0; k < steps; ++k) law.update_stress(p, dt);
    const Matrix2d s = pts.stress(0);
    const double tol = 1e-7 * mu;  // O(dt^2) of the midpoint rotation
    EXPECT_NEAR(s(0, 1), mu * std::sin(gamma_end), tol);
    EXPECT_NEAR(s(0, 0), mu * (1 - std::cos(gamma_end)), tol);
    EXPECT_NEAR(s(1, 1), -mu * (1 - std::cos(gamma_end)), tol);
    EXPECT_NEAR(law.out_of_plane_stress(p, 0), 0.0, 1e-12 * mu);
    if (gamma_end < 0.1) {
      EXPECT_NEAR(s(0, 1) / (mu * gamma_end), 1.0, 2e-5);
    }
  }
}

TEST(Jaumann, TotalFormEqualsTheIncrementalUpdate) {
  // The law evaluates sigma = Q [C : (Q^T eps Q)] Q^T over the co-rotated strain; the
  // incremental step sigma^{n+1} = Rh (Rh sigma Rh^T + dt Qm C : (Qm^T D Qm) Qm^T) Rh^T,
  // Qm = Rh Q^n, Q^{n+1} = Rh Qm, must give the same numbers for a path with spin and
  // stretch, isotropic or cubic.
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n01;
  for (const CubicConstants& c : {iso, kCopperCubic}) {
    PointSet<3> pts(1);
    CubicElastic<3> law(c);
    auto p = pts.view();
    law.initialize(p);
    Matrix3d sigma = Matrix3d::Zero(), Q = Matrix3d::Identity();
    const double dt = 1e-3;
    for (int k = 0; k < 500; ++k) {
      Matrix3d L;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) L(a, b) = 0.5 * n01(rng);
      pts.set_grad_v(L);
      law.update_stress(p, dt);
      const Matrix3d Rh = jaumann::half_step_rotation<3>(jaumann::spin<3>(L), dt);
      const Matrix3d Qm = Rh * Q;
      const Matrix3d D = jaumann::rate_of_deformation<3>(L);
      const Matrix3d increment = dt * Qm * c.stress<3>(Qm.transpose() * D * Qm) * Qm.transpose();
      sigma = jaumann::objective_step<3>(sigma, Rh, increment);
      Q = Rh * Qm;
    }
    EXPECT_LT((pts.stress(0) - sigma).norm(), 1e-11 * sigma.norm()) << "c11 = " << c.c11;
  }
}

}  // namespace
}  // namespace mpmx::material
