#include "mpmx/mpm/step.hpp"

#include <cmath>
#include <typeinfo>

#include "mpmx/material/linear_elastic.hpp"
#include "mpmx/mpm/solve.hpp"
#include "mpmx/mpm/transfer.hpp"
#include "mpmx/mpm/viscosity.hpp"

namespace mpmx::mpm {

namespace {

// Stress work of the step (eq. 4.11, with the stress the forces used), then
// dV/dt = V div v and the domain length where the scheme tracks it; the material's
// stress, the viscosity, the clock.
void finish(State<1>& s, double dt) {
  auto& p = s.particles;
  work_and_volumes(p, dt, s.small_strain, tracks_domain(s.shape->options().scheme), s.tallies);
  s.material->update_stress(p, dt);
  artificial_viscosity(*s.material, s.viscosity, p);
  s.time += dt;
  ++s.step;
}

}  // namespace

void step_stencil(State<1>& s, double dt) {
  auto& g = s.grid;
  auto& p = s.particles;
  (*s.shape)(g, p, s.stencil);                      // nearest nodes afresh, S_ip, G_ip
  p2g(p, s.stencil, s.small_strain, g);             // m_i, v_i^n (eq. 3.16), f_i
  solve_grid(g, s.boundary, s.time, dt, s.tallies); // v^L (eq. 3.12) with boundaries
  s.finite_check = g2p(g, s.stencil, dt, s.move, s.midpoint_gradient, p);  // v_p, x_p, grad v
  finish(s, dt);
}

void step(State<1>& s, double dt) {
  auto& g = s.grid;
  auto& p = s.particles;
  const SchemeOptions& opt = s.shape->options();
  const Scheme scheme = opt.scheme;
  if (scheme == Scheme::mpm) {                        // fused hat + transfers, same algorithm
    shape::p2g_linear(g, p, s.small_strain, s.viscosity <= 0.0, s.linear_cells, g);
    solve_grid(g, s.boundary, s.time, dt, s.tallies);
    // A linear elastic solid without viscosity: g2p, work, volumes and stress in one
    // pass, the same algorithm as finish().
    if (s.viscosity <= 0.0 && typeid(*s.material) == typeid(material::LinearElastic<1>)) {
      const auto& mat = static_cast<const material::LinearElastic<1>&>(*s.material);
      s.finite_check = shape::g2p_linear_elastic(g, s.linear_cells, dt, s.move, s.midpoint_gradient,
                                                 s.small_strain, true, mat.youngs_modulus(), p,
                                                 s.tallies.stress_work);
      s.time += dt;
      ++s.step;
      return;
    }
    s.finite_check = shape::g2p_linear(g, s.linear_cells, dt, s.move, s.midpoint_gradient, p);
  } else if (scheme == Scheme::ddmp || scheme == Scheme::ddmp_subpoints) {
    // Fused DDMP (eq. 3.31, sub-points eqs. 6.1-6.3): same algorithm as the stencil path.
    const int sub = scheme == Scheme::ddmp ? 0 : opt.subpoints;
    shape::p2g_ddmp(g, p, s.small_strain, sub, s.linear_cells, g);
    solve_grid(g, s.boundary, s.time, dt, s.tallies);
    // A linear elastic solid without viscosity: work, volumes and stress in the g2p pass
    // where it can, the same algorithm as finish().
    shape::ElasticUpdate update;
    const bool elastic = s.viscosity <= 0.0 && typeid(*s.material) == typeid(material::LinearElastic<1>);
    if (elastic) {
      update.small_strain = s.small_strain;
      update.youngs_modulus = static_cast<const material::LinearElastic<1>&>(*s.material).youngs_modulus();
    }
    s.finite_check = shape::g2p_ddmp(g, s.linear_cells, dt, s.move, s.midpoint_gradient, sub, p,
                                     elastic ? &update : nullptr);
    if (update.done) {
      s.tallies.stress_work += update.stress_work;
      s.time += dt;
      ++s.step;
      return;
    }
  } else {
    return step_stencil(s, dt);
  }
  finish(s, dt);
}

}  // namespace mpmx::mpm
