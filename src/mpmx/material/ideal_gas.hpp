#pragma once
// Ideal gas, density from mass and current volume:
//   isothermal  p = c^2 rho        (the shock-tube study of dissertation ch. 4),
//   adiabatic   p = K rho^gamma    (gamma law; K = p0 / rho0^gamma kept per point).
// The strain array records the integrated volumetric strain for output only.
#include <cmath>
#include <istream>
#include <ostream>
#include <vector>

#include "mpmx/core/error.hpp"
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
  void initialize(const Points<Dim>& p) override {
    if (mode_ == Mode::adiabatic) {
      entropy_.assign(p.size(), 0.0);
      for (std::size_t q = 0; q < p.size(); ++q) entropy_[q] = -p.stress[0][q] / std::pow(p.density(q), gamma_);
    }
    for (std::size_t q = 0; q < p.size(); ++q) set_pressure(p, q);
  }

  void update_stress(const Points<Dim>& p, double dt) override {
    const std::size_t n = p.size();
#pragma omp parallel for schedule(static) num_threads(this->threads_) if (this->threads_ > 1)
    for (std::size_t q = 0; q < n; ++q) {
      for (int a = 0; a < Dim; ++a) p.strain[a * Dim + a][q] += dt * p.grad_v[a * Dim + a][q];
      set_pressure(p, q);
    }
  }

  double sound_speed(const Points<Dim>& p, std::size_t q) const override {
    if (mode_ == Mode::isothermal) return c_;
    return std::sqrt(gamma_ * pressure(p, q) / p.density(q));
  }

  // Adiabatic: the internal energy p V / (gamma - 1); isothermal: none kept.
  bool keeps_energy_account() const override { return mode_ == Mode::adiabatic; }
  double stored_energy(const Points<Dim>& p, std::size_t q) const override {
    return mode_ == Mode::adiabatic ? pressure(p, q) * p.volume[q] / (gamma_ - 1.0) : 0.0;
  }

  double pressure(const Points<Dim>& p, std::size_t q) const {
    const double rho = p.density(q);
    return mode_ == Mode::isothermal ? c_ * c_ * rho : entropy_[q] * std::pow(rho, gamma_);
  }

  void save(std::ostream& out) const override {
    const std::int64_t n = static_cast<std::int64_t>(entropy_.size());
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(entropy_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  }
  void load(std::istream& in) override {
    std::int64_t n = 0;
    in.read(reinterpret_cast<char*>(&n), sizeof n);
    if (!in || n < 0 || n > (std::int64_t{1} << 34)) throw InputError("checkpoint: the gas state is corrupt");
    entropy_.assign(static_cast<std::size_t>(n), 0.0);
    in.read(reinterpret_cast<char*>(entropy_.data()), static_cast<std::streamsize>(n * sizeof(double)));
    if (!in) throw InputError("checkpoint: the gas state is truncated");
  }

 private:
  void set_pressure(const Points<Dim>& p, std::size_t q) const {
    const double pr = pressure(p, q);
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.stress[a * Dim + b][q] = a == b ? -pr : 0.0;
    p.set_sigma_zz(q, -pr);
  }

  Mode mode_;
  double c_, gamma_;
  std::vector<double> entropy_;  // adiabatic: p / rho^gamma per point
};

}  // namespace mpmx::material
