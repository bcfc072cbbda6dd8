#pragma once
// Linear artificial viscosity q = coef rho c |dv| on compression only (dissertation
// sec. 6.3, coefficient 0.5 there); dv is the velocity jump across the point: in 1-D
// |div v| times its length, in 2-D and 3-D the sum over the axes it is compressed along
// of |D_dd| times its domain's extent along d, so that a uniaxial motion written as a
// 2-D or 3-D deck gets the 1-D q (N1). Off when coef = 0. (The tensor form of eqs.
// 7.8-7.10 is in tensor_viscosity.hpp.)
#include <algorithm>
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
    double div = 0.0, jump = 0.0;
    for (int d = 0; d < Dim; ++d) div += p.grad_v[d * Dim + d][q];
    if constexpr (Dim == 1) jump = std::abs(div) * p.volume[q];
    else
      for (int d = 0; d < Dim; ++d)
        jump += std::max(0.0, -p.grad_v[d * Dim + d][q]) * std::abs(p.length[d * Dim + d][q]);
    p.viscous_pressure[q] = div < 0.0 ? coef * p.density(q) * mat.sound_speed(view, q) * jump : 0.0;
  }
}

}  // namespace mpmx::mpm
