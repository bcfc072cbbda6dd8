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
  } else {
    const Mat D = 0.5 * (L + L.transpose());
    Eigen::SelfAdjointEigenSolver<Mat> eig(D);
    Mat q = Mat::Zero();
    if (eig.eigenvalues().minCoeff() >= 0.0) return q;  // expansion or rest
    const double norm = L.operatorNorm();
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

// Writes the viscous stress of every point into q (row-major [a * Dim + b], overwritten).
// The caller adds it to the Cauchy stress where the internal force is formed; it never
// goes into p.stress, which the laws read back as their state. Call it after
// Material::update_stress of the step, so that the sound speed is the updated state's.
template <int Dim>
void tensor_viscosity(const material::Points<Dim>& p, const material::Material<Dim>& m, double c_L,
                      double c_q, std::array<double*, Dim * Dim> q) {
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  for (std::size_t i = 0; i < p.size(); ++i) {
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
