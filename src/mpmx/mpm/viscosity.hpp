#pragma once
// Linear artificial viscosity q = coef rho c |dv| on compression only (dissertation
// sec. 6.3, coefficient 0.5 there); dv is the velocity jump across the point,
// |div v| times its length. Off when coef = 0. (The tensor form of eqs. 7.8-7.10 is
// in tensor_viscosity.hpp.)
#include <cmath>

#include "mpmx/material/material.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/points.hpp"

namespace mpmx::mpm {

template <int Dim>
void artificial_viscosity(const material::Material<Dim>& mat, double coef, Particles<Dim>& p, int threads = 1) {
  if (coef <= 0.0) return;
  const auto view = points(p);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t q = 0; q < n; ++q) {
    double div = 0.0, len = 0.0;
    for (int d = 0; d < Dim; ++d) div += p.grad_v[d * Dim + d][q];
    if constexpr (Dim == 1) len = p.volume[q];
    else {
      for (int d = 0; d < Dim; ++d) len += std::abs(p.length[d * Dim + d][q]);
      len /= Dim;
    }
    p.viscous_pressure[q] = div < 0.0 ? coef * p.density(q) * mat.sound_speed(view, q) * std::abs(div) * len : 0.0;
  }
}

}  // namespace mpmx::mpm
