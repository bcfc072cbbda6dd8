#pragma once
// The material's view of the solver's particles (material/points.hpp).
#include "mpmx/material/points.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm {

template <int Dim>
material::Points<Dim> points(Particles<Dim>& p) {
  material::Points<Dim> v;
  v.n = p.size();
  for (int c = 0; c < Dim * Dim; ++c) {
    v.grad_v[c] = p.grad_v[c].data();
    v.stress[c] = p.stress[c].data();
    v.strain[c] = p.strain[c].data();
    if (!p.viscous[c].empty()) v.viscous[c] = p.viscous[c].data();
  }
  if (!p.stress_zz.empty()) v.stress_zz = p.stress_zz.data();
  if (!p.viscous_pressure.empty()) v.viscous_pressure = p.viscous_pressure.data();
  v.mass = p.mass.data();
  v.volume = p.volume.data();
  v.volume0 = p.volume0.data();
  for (int d = 0; d < Dim; ++d) v.length[d] = p.length[d * Dim + d].data();
  return v;
}

template <int Dim>
material::Points<Dim> points(const Particles<Dim>& p) {
  return points(const_cast<Particles<Dim>&>(p));  // read-only users take it as const
}

}  // namespace mpmx::mpm
