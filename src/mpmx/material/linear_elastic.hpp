#pragma once
// Linear elastic solid, stress from the integrated strain rate (ADMPM eqs. 1.37-1.38):
// eps += dt sym(grad v); sigma = lambda tr(eps) I + 2 mu eps; in 1-D sigma = E eps.
#include "mpmx/material/material.hpp"

namespace mpmx::material {

template <int Dim>
class LinearElastic final : public Material<Dim> {
 public:
  LinearElastic(double youngs_modulus, double poisson_ratio)
      : E_(youngs_modulus), nu_(poisson_ratio) {}

  std::string name() const override { return "linear_elastic"; }

  void initialize(mpm::Particles<Dim>& p) override {
    for (std::size_t q = 0; q < p.size(); ++q) stress_from_strain(p, q);
  }

  void update_stress(mpm::Particles<Dim>& p, double dt) override {
    if constexpr (Dim == 1) {  // one plain loop that vectorises; 0.5 (L + L) = L exactly
      double* __restrict eps = p.strain[0].data();
      double* __restrict sig = p.stress[0].data();
      const double* __restrict L = p.grad_v[0].data();
      const std::size_t n = p.size();
#pragma omp simd
      for (std::size_t q = 0; q < n; ++q) {
        eps[q] += dt * L[q];
        sig[q] = E_ * eps[q];
      }
      return;
    }
    for (std::size_t q = 0; q < p.size(); ++q) {
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b)
          p.strain[a * Dim + b][q] +=
              dt * 0.5 * (p.grad_v[a * Dim + b][q] + p.grad_v[b * Dim + a][q]);
      stress_from_strain(p, q);
    }
  }

  double sound_speed(const mpm::Particles<Dim>& p, std::size_t q) const override {
    return std::sqrt(p_wave_modulus() / p.density(q));
  }

  double youngs_modulus() const { return E_; }

  double p_wave_modulus() const {
    if (Dim == 1) return E_;
    return E_ * (1.0 - nu_) / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  }

 private:
  void stress_from_strain(mpm::Particles<Dim>& p, std::size_t q) const {
    if constexpr (Dim == 1) {
      p.stress[0][q] = E_ * p.strain[0][q];
    } else {
      const double mu = E_ / (2.0 * (1.0 + nu_));
      const double lambda = E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
      double tr = 0.0;
      for (int a = 0; a < Dim; ++a) tr += p.strain[a * Dim + a][q];
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b)
          p.stress[a * Dim + b][q] = 2.0 * mu * p.strain[a * Dim + b][q] + (a == b ? lambda * tr : 0.0);
    }
  }

  double E_, nu_;
};

}  // namespace mpmx::material
