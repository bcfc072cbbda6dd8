#include "mpmx/material/linear_elastic_model.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/material/linear_elastic.hpp"

namespace mpmx::material {

double LinearElasticModel::wave_speed(int dim, double density, double) const {
  return std::sqrt(std::max(modulus(dim), 0.0) / density);
}
std::unique_ptr<Material<1>> LinearElasticModel::make1() const { return std::make_unique<LinearElastic<1>>(E, nu); }
std::unique_ptr<Material<2>> LinearElasticModel::make2() const { return std::make_unique<LinearElastic<2>>(E, nu); }
std::unique_ptr<Material<3>> LinearElasticModel::make3() const { return std::make_unique<LinearElastic<3>>(E, nu); }

std::shared_ptr<const Model> LinearElasticEntry::read(Table& m, const Context&) {
  auto r = std::make_shared<LinearElasticModel>();
  r->rho = m.number("density", 1.0);
  m.positive("density", r->rho);
  r->E = m.number("youngs_modulus");
  m.positive("youngs_modulus", r->E);
  r->nu = m.number("poisson_ratio", 0.0);
  m.check(r->nu > -1.0 && r->nu < 0.5, "poisson_ratio", "must lie in (-1, 0.5)");
  r->unstrained = m.choice("density_of", {"initial", "unstrained"}, "initial") == "unstrained";
  return r;
}

}  // namespace mpmx::material
