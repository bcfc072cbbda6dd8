#pragma once
// Linear artificial viscosity q = coef rho c |dv| on compression only (dissertation
// sec. 6.3, coefficient 0.5 there); dv is the velocity jump across the point,
// |div v| times its length. Off when coef = 0.
#include <cmath>

#include "mpmx/material/material.hpp"

namespace mpmx::mpm {

inline void artificial_viscosity(const material::Material<1>& mat, double coef, Particles<1>& p) {
  if (coef <= 0.0) return;
  const std::size_t n = p.size();
  for (std::size_t q = 0; q < n; ++q) {
    const double div = p.grad_v[0][q];
    p.viscous_pressure[q] =
        div < 0.0 ? coef * p.density(q) * mat.sound_speed(p, q) * std::abs(div) * p.volume[q] : 0.0;
  }
}

}  // namespace mpmx::mpm
