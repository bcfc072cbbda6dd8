#pragma once
// Ideal gas, density from mass and current volume:
//   isothermal  p = c^2 rho        (the shock-tube study of dissertation ch. 4),
//   adiabatic   p = K rho^gamma    (gamma law; K = p0 / rho0^gamma kept per point).
// The strain array records the integrated volumetric strain for output only.
#include <cmath>

#include "mpmx/material/material.hpp"

namespace mpmx::material {

template <int Dim>
class IdealGas final : public Material<Dim> {
 public:
  enum class Mode { isothermal, adiabatic };

  // isothermal: `c` is the sound speed; adiabatic: `gamma` is the exponent.
  IdealGas(Mode mode, double c, double gamma) : mode_(mode), c_(c), gamma_(gamma) {}

  std::string name() const override {
    return mode_ == Mode::isothermal ? "ideal_gas_isothermal" : "ideal_gas_adiabatic";
  }

  // For the adiabatic gas the caller has put the initial pressure in -stress[0].
  void initialize(mpm::Particles<Dim>& p) override {
    for (std::size_t q = 0; q < p.size(); ++q) {
      if (mode_ == Mode::adiabatic)
        p.entropy[q] = -p.stress[0][q] / std::pow(p.density(q), gamma_);
      set_pressure(p, q);
    }
  }

  void update_stress(mpm::Particles<Dim>& p, double dt) override {
    for (std::size_t q = 0; q < p.size(); ++q) {
      for (int a = 0; a < Dim; ++a) p.strain[a * Dim + a][q] += dt * p.grad_v[a * Dim + a][q];
      set_pressure(p, q);
    }
  }

  double sound_speed(const mpm::Particles<Dim>& p, std::size_t q) const override {
    if (mode_ == Mode::isothermal) return c_;
    return std::sqrt(gamma_ * pressure(p, q) / p.density(q));
  }

  double pressure(const mpm::Particles<Dim>& p, std::size_t q) const {
    const double rho = p.density(q);
    return mode_ == Mode::isothermal ? c_ * c_ * rho : p.entropy[q] * std::pow(rho, gamma_);
  }

 private:
  void set_pressure(mpm::Particles<Dim>& p, std::size_t q) const {
    const double pr = pressure(p, q);
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.stress[a * Dim + b][q] = a == b ? -pr : 0.0;
  }

  Mode mode_;
  double c_, gamma_;
};

}  // namespace mpmx::material
