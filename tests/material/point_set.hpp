#pragma once
// A batch of material points over local vectors, and its Points<Dim> view, for the
// constitutive-law tests (no solver involved).
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/material/points.hpp"

namespace mpmx::test {

// Copper's cubic constants, GPa (the seed's potential is near these).
inline const material::CubicConstants kCopperCubic{170.0, 123.0, 76.0};

template <int Dim>
struct PointSet {
  using Mat = Eigen::Matrix<double, Dim, Dim>;
  static constexpr int T = Dim * Dim;

  std::size_t n;
  std::array<std::vector<double>, T> L, sig, eps;
  std::vector<double> mass, volume, volume0;
  std::array<std::vector<double>, Dim> len;

  // n points of density rho and volume vol, at rest, unstrained, domain edges `edge`.
  explicit PointSet(std::size_t count, double rho = 1.0, double vol = 1.0, double edge = 1.0)
      : n(count), mass(count, rho * vol), volume(count, vol), volume0(count, vol) {
    for (auto* f : {&L, &sig, &eps})
      for (auto& c : *f) c.assign(count, 0.0);
    for (auto& c : len) c.assign(count, edge);
  }

  material::Points<Dim> view() {
    material::Points<Dim> p;
    p.n = n;
    for (int k = 0; k < T; ++k) {
      p.grad_v[k] = L[k].data();
      p.stress[k] = sig[k].data();
      p.strain[k] = eps[k].data();
    }
    p.mass = mass.data();
    p.volume = volume.data();
    p.volume0 = volume0.data();
    for (int a = 0; a < Dim; ++a) p.length[a] = len[a].data();
    return p;
  }

  static void put(std::array<std::vector<double>, T>& f, std::size_t q, const Mat& m) {
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) f[a * Dim + b][q] = m(a, b);
  }
  static Mat get(const std::array<std::vector<double>, T>& f, std::size_t q) {
    Mat m;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) m(a, b) = f[a * Dim + b][q];
    return m;
  }
  void set_grad_v(std::size_t q, const Mat& m) { put(L, q, m); }
  void set_grad_v(const Mat& m) {
    for (std::size_t q = 0; q < n; ++q) put(L, q, m);
  }
  void set_strain(std::size_t q, const Mat& m) { put(eps, q, m); }
  Mat stress(std::size_t q) const { return get(sig, q); }
  Mat strain(std::size_t q) const { return get(eps, q); }
};

// A rotation by `angle` about the unit axis `axis` (3-D), or about z (2-D).
inline Eigen::Matrix3d rotation3(double angle, Eigen::Vector3d axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}
inline Eigen::Matrix2d rotation2(double angle) {
  return Eigen::Rotation2Dd(angle).toRotationMatrix();
}

}  // namespace mpmx::test
