#include "mpmx/md/hugoniot.hpp"

#include <cmath>

#include "mpmx/core/units.hpp"

namespace mpmx::md {

HugoniotPoint jump_conditions(const System& s, double v0, double p0, double v, double p) {
  double mass = 0;  // amu
  for (int t : s.atoms().type) mass += s.type_mass()[t];
  HugoniotPoint h;
  h.rho0 = mass * units::amu_in_kg * 1e3 / (v0 * 1e-24);  // g over cm^3
  const double eta = 1 - v / v0;
  h.us = eta > 0 && p > p0 ? std::sqrt((p - p0) / (h.rho0 * eta)) : 0.0;  // GPa / (g/cm^3) = (km/s)^2
  h.up = h.us * eta;
  return h;
}

}  // namespace mpmx::md
