#include "mpmx/material/ideal_gas_model.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/material/ideal_gas.hpp"

namespace mpmx::material {

double IdealGasModel::wave_speed(int, double density, double pressure) const {
  return isothermal ? c : std::sqrt(gamma * std::max(pressure, 0.0) / density);
}
double IdealGasModel::density_at_pressure(double p) const { return isothermal ? p / (c * c) : std::nan(""); }

template <int Dim>
static std::unique_ptr<Material<Dim>> make_gas(const IdealGasModel& m) {
  using Gas = IdealGas<Dim>;
  return std::make_unique<Gas>(m.isothermal ? Gas::Mode::isothermal : Gas::Mode::adiabatic, m.c,
                               m.isothermal ? 1.0 : m.gamma);
}
std::unique_ptr<Material<1>> IdealGasModel::make1() const { return make_gas<1>(*this); }
std::unique_ptr<Material<2>> IdealGasModel::make2() const { return make_gas<2>(*this); }
std::unique_ptr<Material<3>> IdealGasModel::make3() const { return make_gas<3>(*this); }

std::shared_ptr<const Model> IdealGasIsothermalEntry::read(Table& m, const Context&) {
  auto r = std::make_shared<IdealGasModel>();
  r->isothermal = true;
  r->rho = m.number("density", 1.0);
  m.positive("density", r->rho);
  r->c = m.number("sound_speed");
  m.positive("sound_speed", r->c);
  return r;
}

std::shared_ptr<const Model> IdealGasAdiabaticEntry::read(Table& m, const Context&) {
  auto r = std::make_shared<IdealGasModel>();
  r->isothermal = false;
  r->rho = m.number("density", 1.0);
  m.positive("density", r->rho);
  r->gamma = m.number("gamma", 1.4);
  m.check(r->gamma > 1.0, "gamma", "must exceed 1");
  return r;
}

}  // namespace mpmx::material
