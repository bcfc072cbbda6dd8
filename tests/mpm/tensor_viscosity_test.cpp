// ctest-label: unit
// The tensor artificial viscosity of dissertation eqs. 7.8-7.10 (mpm/tensor_viscosity.hpp):
// zero for expansion and rigid rotation, q_xx only and the hand value of eq. 7.8 for
// uniaxial compression, the 1-D linear + quadratic form, frame invariance.
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/mpm/tensor_viscosity.hpp"
#include "material/point_set.hpp"

namespace mpmx::mpm {
namespace {

using material::CubicConstants;
using material::CubicElastic;
using test::PointSet;

// rho = 2, an isotropic solid with C11 = 8: a = sqrt(C11 / rho) = 2; l = 0.2.
constexpr double rho = 2.0, a = 2.0, l = 0.2, cL = 1.5, cq = 2.0;
const CubicConstants iso{8.0, 2.0, 3.0};

template <int Dim>
struct Batch {
  PointSet<Dim> pts;
  CubicElastic<Dim> law{iso};
  std::array<std::vector<double>, Dim * Dim> q;
  explicit Batch(std::size_t n = 1) : pts(n, rho, 1.0) {
    // Domain edges averaging to l: 0.2 (1-D), 0.1 and 0.3 (2-D), 0.1, 0.3, 0.2 (3-D).
    const double edges[3] = {Dim == 1 ? 0.2 : 0.1, 0.3, 0.2};
    for (int d = 0; d < Dim; ++d) pts.len[d].assign(n, edges[d]);
    for (auto& c : q) c.assign(n, 1e300);  // overwritten
  }
  typename PointSet<Dim>::Mat run(const typename PointSet<Dim>::Mat& L, std::size_t i = 0) {
    pts.set_grad_v(L);
    std::array<double*, Dim * Dim> out;
    for (int k = 0; k < Dim * Dim; ++k) out[k] = q[k].data();
    tensor_viscosity<Dim>(pts.view(), law, cL, cq, out);
    return PointSet<Dim>::get(q, i);
  }
};

TEST(TensorViscosity, CharacteristicLengthAndSoundSpeed) {
  Batch<2> s;
  EXPECT_DOUBLE_EQ(s.law.sound_speed(s.pts.view(), 0), a);
}

TEST(TensorViscosity, ZeroForExpansionAndRigidRotation) {
  Batch<2> s2;
  Eigen::Matrix2d L2;
  L2 << 1.0, 0.5, 0.0, 2.0;  // D positive definite
  EXPECT_EQ(s2.run(L2).norm(), 0.0);
  L2 << 0.0, -3.0, 3.0, 0.0;  // rigid rotation
  EXPECT_EQ(s2.run(L2).norm(), 0.0);
  Batch<3> s3;
  Eigen::Matrix3d L3;
  L3 << 0.0, -1.0, 2.0, 1.0, 0.0, -0.5, -2.0, 0.5, 0.0;
  EXPECT_EQ(s3.run(L3).norm(), 0.0);
  EXPECT_EQ(s3.run(Eigen::Matrix3d::Identity() + L3).norm(), 0.0);  // expansion + spin
  Batch<1> s1;
  EXPECT_EQ(s1.run(Eigen::Matrix<double, 1, 1>(4.0))(0, 0), 0.0);
}

TEST(TensorViscosity, UniaxialCompressionGivesEq78ByHand) {
  // L = diag(-3, 0, 0): lambda = -3, g = e_x, tau0 = |-3| / 3 = 1,
  // q_xx = rho l lambda (tau0 c_L a - c_q l lambda) = 2 * 0.2 * (-3) * (3 + 1.2) = -5.04.
  const double expect = -5.04;
  Batch<1> s1;
  EXPECT_NEAR(s1.run(Eigen::Matrix<double, 1, 1>(-3.0))(0, 0), expect, 1e-14);
  Batch<2> s2;
  Eigen::Matrix2d L2 = Eigen::Matrix2d::Zero();
  L2(0, 0) = -3.0;
  const Eigen::Matrix2d q2 = s2.run(L2);
  EXPECT_NEAR(q2(0, 0), expect, 1e-14);
  EXPECT_EQ(q2(1, 1), 0.0);
  EXPECT_EQ(q2(0, 1), 0.0);
  EXPECT_EQ(q2(1, 0), 0.0);
  Batch<3> s3;
  Eigen::Matrix3d L3 = Eigen::Matrix3d::Zero();
  L3(0, 0) = -3.0;
  const Eigen::Matrix3d q3 = s3.run(L3);
  EXPECT_NEAR(q3(0, 0), expect, 1e-14);
  EXPECT_LT((q3 - expect * Eigen::Vector3d::UnitX() * Eigen::Vector3d::UnitX().transpose()).norm(), 1e-14);
  // Compression along y only: q_yy, the same value.
  Eigen::Matrix3d Ly = Eigen::Matrix3d::Zero();
  Ly(1, 1) = -3.0;
  EXPECT_NEAR(s3.run(Ly)(1, 1), expect, 1e-14);
  EXPECT_NEAR(s3.run(Ly)(0, 0), 0.0, 1e-15);
}

TEST(TensorViscosity, OneDimensionIsLinearPlusQuadratic) {
  // q = -(c_L rho a l |L| + c_q rho l^2 L^2) on compression.
  Batch<1> s;
  for (const double L : {-0.01, -1.0, -50.0}) {
    const double expect = -(cL * rho * a * l * std::abs(L) + cq * rho * l * l * L * L);
    EXPECT_NEAR(s.run(Eigen::Matrix<double, 1, 1>(L))(0, 0), expect, 1e-14 * std::abs(expect));
  }
}

TEST(TensorViscosity, IsotropicCompressionAndIsochoricShear) {
  // L = -lambda I in 3-D: tau0 = 3 lambda / lambda = 3 (spectral norm), q isotropic.
  Batch<3> s3;
  const double lam = 2.0;
  const Eigen::Matrix3d q = s3.run(-lam * Eigen::Matrix3d::Identity());
  const double qi = rho * l * (-lam) * (3 * cL * a + cq * l * lam);
  EXPECT_LT((q - qi * Eigen::Matrix3d::Identity()).norm(), 1e-13 * std::abs(qi));
  // Pure shear D = [[0, g], [g, 0]]: tau0 = 0; the compressive direction (1, -1)/sqrt 2
  // gets the quadratic term alone, -c_q rho l^2 g^2 along it.
  Batch<2> s2;
  const double g = 1.5;
  Eigen::Matrix2d L;
  L << 0.0, g, g, 0.0;
  const Eigen::Matrix2d q2 = s2.run(L);
  const double m = -cq * rho * l * l * g * g;
  EXPECT_NEAR(q2(0, 0), 0.5 * m, 1e-14);
  EXPECT_NEAR(q2(1, 1), 0.5 * m, 1e-14);
  EXPECT_NEAR(q2(0, 1), -0.5 * m, 1e-14);
  EXPECT_NEAR(q2(1, 0), -0.5 * m, 1e-14);
}

template <int Dim>
void frame_invariance() {
  using Mat = typename PointSet<Dim>::Mat;
  std::mt19937_64 rng(Dim);
  std::normal_distribution<double> n01;
  int compressive = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Mat L;
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) L(i, j) = n01(rng) - (i == j ? 0.3 : 0.0);
    Mat R;
    if constexpr (Dim == 2) R = test::rotation2(3.0 * n01(rng));
    else R = test::rotation3(3.0 * n01(rng), Eigen::Vector3d(n01(rng), n01(rng), n01(rng)));
    Batch<Dim> s;
    const Mat q = s.run(L);
    const Mat qr = s.run(R * L * R.transpose());
    EXPECT_LT((qr - R * q * R.transpose()).norm(), 1e-13 * std::max(q.norm(), 1e-300));
    EXPECT_LT((q - q.transpose()).norm(), 1e-15 * q.norm() + 1e-300);
    // Negative semi-definite: it resists compression, never pulls.
    EXPECT_LE(Eigen::SelfAdjointEigenSolver<Mat>(q).eigenvalues().maxCoeff(), 1e-14 * q.norm());
    compressive += q.norm() > 0.0;
  }
  EXPECT_GT(compressive, 150);
}

// Eqs. 7.8-7.10 as written, with Eigen's iterative eigensolver and operator norm: the
// closed forms of tensor_viscosity_of (2-D exact to round-off, 3-D Eigen's direct
// solver) agree with it, also near uniaxial compression (a shock's gradient).
template <int Dim>
void closed_form_agrees(double tol) {
  using Mat = typename PointSet<Dim>::Mat;
  std::mt19937_64 rng(10 + Dim);
  std::normal_distribution<double> n01;
  double worst = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    Mat L;
    for (int i = 0; i < Dim; ++i)
      for (int j = 0; j < Dim; ++j) L(i, j) = n01(rng);
    if (trial % 2) {  // uniaxial compression with a small rest
      L *= 1e-3;
      L(0, 0) -= 5.0;
    }
    const Mat D = 0.5 * (L + L.transpose());
    Eigen::SelfAdjointEigenSolver<Mat> eig(D);
    const double norm = L.operatorNorm(), tau0 = norm > 0.0 ? std::abs(L.trace()) / norm : 0.0;
    Mat ref = Mat::Zero();
    for (int k = 0; k < Dim; ++k) {
      const double lambda = eig.eigenvalues()(k);
      if (lambda < 0.0)
        ref += (rho * l * lambda * (tau0 * cL * a - cq * l * lambda)) * eig.eigenvectors().col(k) *
               eig.eigenvectors().col(k).transpose();
    }
    const Mat q = tensor_viscosity_of<Dim>(L, rho, l, a, cL, cq);
    worst = std::max(worst, (q - ref).norm() / std::max(ref.norm(), 1e-300));
    EXPECT_EQ(q(0, 1), q(1, 0));
  }
  EXPECT_LT(worst, tol) << Dim << "-D";
}

TEST(TensorViscosity, ClosedFormsAgreeWithTheIterativeEigensolver) {
  closed_form_agrees<2>(1e-13);
  closed_form_agrees<3>(1e-11);
}

// Every point on its own: one thread and two give the same bits.
TEST(TensorViscosity, SameBitsOnOneThreadAndTwo) {
  constexpr std::size_t n = 999;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01;
  Batch<3> s(n);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Matrix3d L;
    for (int k = 0; k < 9; ++k) L(k) = n01(rng);
    s.pts.set_grad_v(i, L);
  }
  std::array<std::array<std::vector<double>, 9>, 2> out;
  for (int t = 0; t < 2; ++t) {
    std::array<double*, 9> q;
    for (int k = 0; k < 9; ++k) {
      out[t][k].assign(n, 1e300);
      q[k] = out[t][k].data();
    }
    tensor_viscosity<3>(s.pts.view(), s.law, cL, cq, q, t + 1);
  }
  EXPECT_EQ(out[0], out[1]);
}

TEST(TensorViscosity, TurnsWithTheFrame) {
  frame_invariance<2>();
  frame_invariance<3>();
}

TEST(TensorViscosity, EveryPointOfABatch) {
  // Two points, one compressed and one expanding: each gets its own q.
  Batch<2> s(2);
  Eigen::Matrix2d Lc = Eigen::Matrix2d::Zero(), Le = Eigen::Matrix2d::Zero();
  Lc(0, 0) = -3.0;
  Le(0, 0) = 3.0;
  s.pts.set_grad_v(0, Lc);
  s.pts.set_grad_v(1, Le);
  std::array<double*, 4> out{s.q[0].data(), s.q[1].data(), s.q[2].data(), s.q[3].data()};
  tensor_viscosity<2>(s.pts.view(), s.law, cL, cq, out);
  EXPECT_NEAR(s.q[0][0], -5.04, 1e-14);
  EXPECT_EQ(s.q[0][1], 0.0);
  for (int k = 1; k < 4; ++k) EXPECT_EQ(s.q[k][0], 0.0);
}

}  // namespace
}  // namespace mpmx::mpm
