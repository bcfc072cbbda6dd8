#pragma once
// The [material] table of model = "linear_elastic".
#include "mpmx/material/model.hpp"

namespace mpmx::material {

// The registry entry (app/mpm/materials.hpp).
struct LinearElasticEntry {
  static constexpr std::string_view name = "linear_elastic";
  static std::shared_ptr<const Model> read(Table& m, const Context& ctx);
};

struct LinearElasticModel final : Model {
  double rho = 1.0, E = 1.0, nu = 0.0;
  bool unstrained = false;

  std::string name() const override { return std::string(LinearElasticEntry::name); }
  double density() const override { return rho; }
  bool solid() const override { return true; }
  bool density_of_unstrained() const override { return unstrained; }
  // The P-wave modulus of uniaxial strain: E in 1-D, lambda + 2 mu otherwise.
  double modulus(int dim) const {
    return dim == 1 ? E : E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }
  double wave_speed(int dim, double density, double) const override;
  std::optional<IsotropicElastic> isotropic_elastic() const override { return IsotropicElastic{E, nu}; }
  double uniaxial_modulus() const override { return E; }
  std::unique_ptr<Material<1>> make1() const override;
  std::unique_ptr<Material<2>> make2() const override;
  std::unique_ptr<Material<3>> make3() const override;
};


}  // namespace mpmx::material
