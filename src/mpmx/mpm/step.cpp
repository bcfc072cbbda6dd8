#include "mpmx/mpm/step.hpp"

#include <cmath>

#include "mpmx/mpm/solve.hpp"
#include "mpmx/mpm/transfer.hpp"
#include "mpmx/mpm/viscosity.hpp"

namespace mpmx::mpm {

void step(State<1>& s, double dt) {
  auto& g = s.grid;
  auto& p = s.particles;
  (*s.shape)(g, p, s.stencil);                        // nearest nodes afresh, S_ip, G_ip
  p2g(p, s.stencil, s.small_strain, g);               // m_i, v_i^n (eq. 3.16), f_i
  solve_grid(g, s.boundary, s.time, dt, s.tallies);   // v^L (eq. 3.12) with boundaries
  g2p(g, s.stencil, dt, s.move, s.midpoint_gradient, p);  // v_p, x_p, grad v
  account_stress_work(p, dt, s.small_strain, s.tallies);  // eq. 4.11, before sigma changes
  update_volumes(p, dt, tracks_domain(s.shape->options().scheme));  // dV/dt = V div v
  s.material->update_stress(p, dt);
  artificial_viscosity(*s.material, s.viscosity, p);
  s.time += dt;
  ++s.step;
}

}  // namespace mpmx::mpm
