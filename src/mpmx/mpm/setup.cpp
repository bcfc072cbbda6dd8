#include "mpmx/mpm/setup.hpp"

#include <cmath>

#include "mpmx/material/ideal_gas.hpp"
#include "mpmx/material/linear_elastic.hpp"
#include "mpmx/material/md_closure.hpp"

namespace mpmx::mpm {

std::unique_ptr<material::Material<1>> make_material(const MaterialConfig& m) {
  using Gas = material::IdealGas<1>;
  if (m.model == "linear_elastic")
    return std::make_unique<material::LinearElastic<1>>(m.youngs_modulus, m.poisson_ratio);
  if (m.model == "md_closure") return std::make_unique<material::MdClosure>(m.md);
  if (m.model == "ideal_gas_isothermal")
    return std::make_unique<Gas>(Gas::Mode::isothermal, m.sound_speed, 1.0);
  return std::make_unique<Gas>(Gas::Mode::adiabatic, 0.0, m.gamma);
}

State<1> make_state(const MpmConfig& c, bool initialize_material) {
  State<1> s;
  s.grid = Grid<1>({c.lower}, {c.upper}, {c.cells});
  s.move = c.move;
  s.small_strain = c.material.small_strain;
  s.midpoint_gradient = c.scheme.midpoint_gradient;
  s.viscosity = c.viscosity;
  s.boundary = c.boundary;
  s.material = make_material(c.material);

  const double dx = c.dx(), L = c.upper - c.lower;
  const std::size_t n = static_cast<std::size_t>(c.cells) * c.per_cell;
  auto& p = s.particles;
  p.resize(n);
  const double l = dx / c.per_cell;
  const bool solid = c.material.solid();
  const bool isothermal = c.material.model == "ideal_gas_isothermal";
  for (std::size_t q = 0; q < n; ++q) {
    const double x = c.lower + (static_cast<double>(q) + 0.5) * l;
    p.x[0][q] = x;
    p.length[0][q] = l;
    p.volume[q] = p.volume0[q] = l;
    p.v[0][q] = c.velocity(x, c.lower, L, dx);
    double rho = c.material.density;
    if (solid) {
      p.strain[0][q] = c.strain(x, c.lower, L, dx);
      if (c.material.density_unstrained) rho /= 1.0 + p.strain[0][q];
    } else {
      const double pr = c.pressure(x, c.lower, L, dx);
      if (isothermal) rho = pr / (c.material.sound_speed * c.material.sound_speed);
      p.stress[0][q] = -pr;  // read by the adiabatic gas to fix its entropy
    }
    p.mass[q] = rho * l;
  }
  if (initialize_material) s.material->initialize(p);
  s.shape = std::make_unique<ShapeEvaluator>(c.scheme, s.grid);
  return s;
}

}  // namespace mpmx::mpm
