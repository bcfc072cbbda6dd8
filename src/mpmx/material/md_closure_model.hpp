#pragma once
// The [material] table of model = "md_closure": [material.potential] and
// [material.md]. The crystal's density and C11 (continuum units) come from the
// potential itself.
#include "mpmx/material/md_closure.hpp"
#include "mpmx/material/registry.hpp"

namespace mpmx::material {

struct MdClosureModel final : Model {
  MdClosureConfig md;
  double rho = 1.0, c11 = 1.0;   // the unstrained crystal's, continuum units

  std::string name() const override { return "md_closure"; }
  double density() const override { return rho; }
  bool solid() const override { return true; }
  bool density_of_unstrained() const override { return true; }
  double wave_speed(int, double density, double) const override;
  std::unique_ptr<Material<1>> make1() const override;
  std::unique_ptr<Material<2>> make2() const override;
  std::unique_ptr<Material<3>> make3() const override;
};

std::shared_ptr<const Model> read_md_closure(io::Section& m, const Context& ctx);

}  // namespace mpmx::material
