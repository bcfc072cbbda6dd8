#pragma once
// The tensor artificial viscosity of dissertation eqs. 7.8-7.10 (its ref. [57]):
//
//   q_ij = sum_k rho l Q_ijk (tau0 c_L a - c_q l lambda_k),     Q_k = lambda_k g_k g_k^T,
//   tau0 = |div v| / ||grad v||_2,
//
// over the negative eigenvalues lambda_k of the strain rate D = sym(grad v) with unit
// eigenvectors g_k; rho the point's density, a its sound speed (Material::sound_speed),
// l its characteristic length, the average of its domain lengths (the dissertation:
// "an average of x and y-lengths of the material point"), c_L = 1.5 and c_q = 2.0 there.
// ||.||_2 is the spectral norm (largest singular value of grad v); tau0 = 0 where
// grad v = 0. tau0 is 1 for uniaxial compression and 0 for isochoric flow, so the
// linear (c_L) term only acts where the point changes volume.
//
// q is a stress (tension positive): every term is lambda_k < 0 times a positive factor,
// so q is negative semi-definite and resists compression along each g_k; it is zero
// for expansion (no negative eigenvalue) and for rigid rotation (D = 0), and it turns
// with the frame (D -> R D R^T gives q -> R q R^T). An isochoric shear still has one
// compressive direction and gets the quadratic term along it.
//
// In 1-D (D = L = dv/dx, g = 1, tau0 = 1) it is the linear + quadratic
// (Landshoff + von Neumann-Richtmyer) viscosity
//   q = -(c_L rho a l |L| + c_q rho l^2 L^2)   for L < 0,   0 for L >= 0,
// with l |L| the velocity jump across the point.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Dense>

#include "mpmx/material/material.hpp"
#include "mpmx/material/points.hpp"

namespace mpmx::mpm {

// q of one point from its velocity gradient L, density rho, length l and sound speed a.
template <int Dim>
Eigen::Matrix<double, Dim, Dim> tensor_viscosity_of(const Eigen::Matrix<double, Dim, Dim>& L, double rho,
                                                    double l, double a, double c_L, double c_q) {
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  if constexpr (Dim == 1) {
    const double lambda = L(0, 0);
    Mat q;
    q(0, 0) = lambda < 0.0 ? rho * l * lambda * (c_L * a - c_q * l * lambda) : 0.0;
    return q;
  } else if constexpr (Dim == 2) {
    // In closed form: an iterative eigensolver here took most of a 2-D step. A symmetric
    // [[m + h, b], [b, m - h]] has the eigenvalues m -+ r, r = |(h, b)| (Mohr's circle);
    // the eigenvector of m + r is (h + r, b) or (b, r - h), whichever adds like signs, the
    // other its normal. ||L||_2^2 is the larger eigenvalue of L^T L.
    struct Circle {
      double m, h, b, r;
    };
    auto circle = [](double xx, double yy, double xy) {
      const double h = 0.5 * (xx - yy);
      return Circle{0.5 * (xx + yy), h, xy, std::sqrt(h * h + xy * xy)};
    };
    const auto [m, h, b, r] = circle(L(0, 0), L(1, 1), 0.5 * (L(0, 1) + L(1, 0)));
    const double lambda[2] = {m - r, m + r};
    if (lambda[0] >= 0.0) return Mat::Zero();  // expansion or rest
    const double x = h >= 0.0 ? h + r : b, y = h >= 0.0 ? b : r - h, len = std::sqrt(x * x + y * y);
    const double c = len > 0.0 ? x / len : 1.0, s = len > 0.0 ? y / len : 0.0;  // len = 0: D = m I
    const double g[2][2] = {{-s, c}, {c, s}};
    const Mat M = L.transpose() * L;
    const Circle LtL = circle(M(0, 0), M(1, 1), M(0, 1));
    const double norm = std::sqrt(LtL.m + LtL.r);
    const double tau0 = norm > 0.0 ? std::abs(L.trace()) / norm : 0.0;
    Mat q = Mat::Zero();
    for (int k = 0; k < 2; ++k) {
      if (!(lambda[k] < 0.0)) continue;
      const double f = rho * l * lambda[k] * (tau0 * c_L * a - c_q * l * lambda[k]);
      q(0, 0) += f * g[k][0] * g[k][0];
      q(1, 1) += f * g[k][1] * g[k][1];
      q(0, 1) += f * g[k][0] * g[k][1];
    }
    q(1, 0) = q(0, 1);
    return q;
  } else {
    // Eigen's closed form of the symmetric 3 x 3 problem (the iterative solver costs
    // several times more); ||L||_2^2 the largest eigenvalue of L L^T.
    const Mat D = 0.5 * (L + L.transpose());
    Eigen::SelfAdjointEigenSolver<Mat> eig;
    eig.computeDirect(D);
    Mat q = Mat::Zero();
    if (eig.eigenvalues().minCoeff() >= 0.0) return q;  // expansion or rest
    Eigen::SelfAdjointEigenSolver<Mat> sq;
    sq.computeDirect(L * L.transpose(), Eigen::EigenvaluesOnly);
    const double norm = std::sqrt(std::max(sq.eigenvalues().maxCoeff(), 0.0));
    const double tau0 = norm > 0.0 ? std::abs(L.trace()) / norm : 0.0;
    for (int k = 0; k < Dim; ++k) {
      const double lambda = eig.eigenvalues()(k);
      if (!(lambda < 0.0)) continue;
      const auto g = eig.eigenvectors().col(k);
      q += (rho * l * lambda * (tau0 * c_L * a - c_q * l * lambda)) * (g * g.transpose());
    }
    return 0.5 * (q + q.transpose());
  }
}

// The kinematic coefficient nu (q ~ rho nu D) of the tensor viscosity at gradient L, length
// l, sound speed a: l (tau0 c_L a + c_q l |lambda_min|) where D has a negative eigenvalue,
// else 0. Its explicit limit is the step's (mpm/step_limit.hpp).
template <int Dim>
double tensor_viscosity_coefficient(const Eigen::Matrix<double, Dim, Dim>& L, double l, double a, double c_L,
                                    double c_q) {
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  if constexpr (Dim == 1) return L(0, 0) < 0.0 ? l * (c_L * a - c_q * l * L(0, 0)) : 0.0;
  const Mat D = 0.5 * (L + L.transpose());
  Eigen::SelfAdjointEigenSolver<Mat> eig;
  eig.computeDirect(D, Eigen::EigenvaluesOnly);
  const double lambda = eig.eigenvalues().minCoeff();
  if (!(lambda < 0.0)) return 0.0;
  Eigen::SelfAdjointEigenSolver<Mat> sq;
  sq.computeDirect(L * L.transpose(), Eigen::EigenvaluesOnly);
  const double norm = std::sqrt(std::max(sq.eigenvalues().maxCoeff(), 0.0));
  const double tau0 = norm > 0.0 ? std::abs(L.trace()) / norm : 0.0;
  return l * (tau0 * c_L * a - c_q * l * lambda);
}

// Writes the viscous stress of every point into q (row-major [a * Dim + b], overwritten).
// The caller adds it to the Cauchy stress where the internal force is formed; it never
// goes into p.stress, which the laws read back as their state. Call it after
// Material::update_stress of the step, so that the sound speed is the updated state's.
// Each point on its own: the same q for any thread count.
template <int Dim>
void tensor_viscosity(const material::Points<Dim>& p, const material::Material<Dim>& m, double c_L,
                      double c_q, std::array<double*, Dim * Dim> q, int threads = 1) {
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t i = 0; i < n; ++i) {
    Mat L;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) L(a, b) = p.grad_v[a * Dim + b][i];
    double l = 0.0;
    for (int a = 0; a < Dim; ++a) l += p.length[a][i];
    l /= Dim;
    const Mat qi = tensor_viscosity_of<Dim>(L, p.density(i), l, m.sound_speed(p, i), c_L, c_q);
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) q[a * Dim + b][i] = qi(a, b);
  }
}

}  // namespace mpmx::mpm
