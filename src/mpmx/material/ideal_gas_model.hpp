#pragma once
// The [material] tables of model = "ideal_gas_isothermal" and "ideal_gas_adiabatic".
#include "mpmx/material/model.hpp"

namespace mpmx::material {

struct IdealGasModel final : Model {
  bool isothermal = true;
  double rho = 1.0;
  double c = 1.0;        // isothermal sound speed
  double gamma = 1.4;    // adiabatic exponent

  std::string name() const override { return isothermal ? "ideal_gas_isothermal" : "ideal_gas_adiabatic"; }
  double density() const override { return rho; }
  bool solid() const override { return false; }
  double wave_speed(int dim, double density, double pressure) const override;
  double density_at_pressure(double p) const override;
  std::optional<GasLaw> gas_law() const override { return GasLaw{rho, c, gamma, isothermal}; }
  std::unique_ptr<Material<1>> make1() const override;
  std::unique_ptr<Material<2>> make2() const override;
  std::unique_ptr<Material<3>> make3() const override;
};

// The registry entries (app/mpm/materials.hpp).
struct IdealGasIsothermalEntry {
  static constexpr std::string_view name = "ideal_gas_isothermal";
  static std::shared_ptr<const Model> read(Table& m, const Context& ctx);
};
struct IdealGasAdiabaticEntry {
  static constexpr std::string_view name = "ideal_gas_adiabatic";
  static std::shared_ptr<const Model> read(Table& m, const Context& ctx);
};

}  // namespace mpmx::material
