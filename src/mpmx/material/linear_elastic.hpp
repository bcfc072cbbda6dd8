#pragma once
// Linear elastic solid. In 1-D the stress follows the integrated strain (ADMPM eqs.
// 1.37-1.38): eps += dt grad v; sigma = E eps. In 2-D (plane strain) and 3-D it is
// hypoelastic with the Jaumann rate, sigma_dot = lambda tr(D) I + 2 mu D + W sigma -
// sigma W, so that a rigid rotation carries the stress along and creates none (the
// Hughes-Winget step of jaumann.hpp).
#include <cmath>

#include "mpmx/material/jaumann.hpp"
#include "mpmx/material/material.hpp"

namespace mpmx::material {

#include "mpmx/material/linear_elastic_1d.inc"

template <int Dim>
class LinearElastic final : public Material<Dim> {
 public:
  LinearElastic(double youngs_modulus, double poisson_ratio)
      : E_(youngs_modulus), nu_(poisson_ratio), fused_{youngs_modulus} {}

  std::string name() const override { return "linear_elastic"; }

  void initialize(const Points<Dim>& p) override {
    for (std::size_t q = 0; q < p.size(); ++q) stress_from_strain(p, q);
  }

  void update_stress(const Points<Dim>& p, double dt) override {
    const std::size_t n = p.size();
    if constexpr (Dim == 1) {  // one plain loop that vectorises
      double* __restrict eps = p.strain[0];
      double* __restrict sig = p.stress[0];
      const double* __restrict L = p.grad_v[0];
      const auto muladd = [](double a, double b, double c) { return a * b + c; };
#pragma omp simd
      for (std::size_t q = 0; q < n; ++q) sig[q] = elastic_1d(eps[q], L[q], dt, E_, muladd);
    } else {
      const double mu = shear_modulus(), lambda = lame_lambda();
#pragma omp parallel for schedule(static) num_threads(this->threads_) if (this->threads_ > 1)
      for (std::size_t q = 0; q < n; ++q) {
        const jaumann::Mat<Dim> L = jaumann::gather<Dim>(p.grad_v, q);
        const jaumann::Mat<Dim> D = jaumann::rate_of_deformation<Dim>(L);
        const jaumann::Mat<Dim> rate =
            2.0 * mu * D + lambda * D.trace() * jaumann::Mat<Dim>::Identity();
        const jaumann::Mat<Dim> Rh = jaumann::half_step_rotation<Dim>(jaumann::spin<Dim>(L), dt);
        const jaumann::Mat<Dim> sig = jaumann::objective_step<Dim>(jaumann::gather<Dim>(p.stress, q), Rh, dt * rate);
        jaumann::scatter<Dim>(sig, q, p.stress);
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b) p.eps(q, a, b) += dt * D(a, b);
        if constexpr (Dim == 2) p.set_sigma_zz(q, lambda * (p.eps(q, 0, 0) + p.eps(q, 1, 1)));  // eps_zz = 0
      }
    }
  }

  double sound_speed(const Points<Dim>& p, std::size_t q) const override {
    return std::sqrt(p_wave_modulus() / p.density(q));
  }

  // 1/2 sigma : eps over the reference volume (ADMPM eq. 8.26 in 1-D).
  bool keeps_energy_account() const override { return true; }
  double stored_energy(const Points<Dim>& p, std::size_t q) const override {
    double w = 0.0;
    for (int c = 0; c < Dim * Dim; ++c) w += p.stress[c][q] * p.strain[c][q];
    return 0.5 * p.volume0[q] * w;
  }

  // In eight lanes by the point's place in the range, added in lane order.
  double stored_energy_sum(const Points<Dim>& p, std::size_t begin, std::size_t end) const override {
    constexpr std::size_t kLanes = 8;
    double lane[kLanes] = {};
    std::size_t q = begin;
    for (; q + kLanes <= end; q += kLanes)
      for (std::size_t l = 0; l < kLanes; ++l) {
        double w = 0.0;
        for (int c = 0; c < Dim * Dim; ++c) w += p.stress[c][q + l] * p.strain[c][q + l];
        lane[l] += 0.5 * p.volume0[q + l] * w;
      }
    for (std::size_t l = 0; q < end; ++q, ++l) lane[l] += stored_energy(p, q);
    double s = 0.0;
    for (double x : lane) s += x;
    return s;
  }

  bool stored_energy_in_1d() const override { return Dim == 1; }
  const FusedElastic1d* fused_elastic() const override { return Dim == 1 ? &fused_ : nullptr; }

  double youngs_modulus() const { return E_; }
  double shear_modulus() const { return E_ / (2.0 * (1.0 + nu_)); }
  double lame_lambda() const { return E_ * nu_ / ((1.0 + nu_) * (1.0 - 2.0 * nu_)); }
  double p_wave_modulus() const {
    if (Dim == 1) return E_;
    return E_ * (1.0 - nu_) / ((1.0 + nu_) * (1.0 - 2.0 * nu_));
  }

 private:
  // The initial stress of an initial strain (zero rotation: no history yet).
  void stress_from_strain(const Points<Dim>& p, std::size_t q) const {
    if constexpr (Dim == 1) {
      p.stress[0][q] = E_ * p.strain[0][q];
    } else {
      const double mu = shear_modulus(), lambda = lame_lambda();
      double tr = 0.0;
      for (int a = 0; a < Dim; ++a) tr += p.eps(q, a, a);
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.sigma(q, a, b) = 2.0 * mu * p.eps(q, a, b) + (a == b ? lambda * tr : 0.0);
      if constexpr (Dim == 2) p.set_sigma_zz(q, lambda * tr);  // plane strain: eps_zz = 0
    }
  }

  double E_, nu_;
  FusedElastic1d fused_;
};

}  // namespace mpmx::material
