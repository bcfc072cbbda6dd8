#include "mpmx/mpm/step.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/mpm/mass_distribution.hpp"
#include "mpmx/mpm/musl.hpp"
#include "mpmx/mpm/piston_grid.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/shape/hat.hpp"
#include "mpmx/mpm/solve.hpp"
#include "mpmx/mpm/tensor_viscosity.hpp"
#include "mpmx/mpm/transfer.hpp"
#include "mpmx/mpm/viscosity.hpp"

namespace mpmx::mpm {

namespace {

// Stress work of the step (eq. 4.11, with the stress the forces used), then
// dV/dt = V div v and the domain where the scheme tracks it; the material's stress, the
// artificial viscosity, the clock.
template <int Dim>
void finish(State<Dim>& s, double dt) {
  auto& p = s.particles;
  work_and_volumes(p, dt, s.small_strain, tracks_domain(s.shape->options().scheme), s.tallies, s.threads);
  const auto view = points(p);
  s.material->update_stress(view, dt);
  artificial_viscosity(*s.material, s.viscosity, p, s.threads);
  if (s.tensor_viscosity.on) {
    std::array<double*, Dim * Dim> q;
    for (int c = 0; c < Dim * Dim; ++c) q[c] = p.viscous[c].data();
    tensor_viscosity<Dim>(view, *s.material, s.tensor_viscosity.c_L, s.tensor_viscosity.c_q, q, s.threads);
    s.material->add_viscous_heat(view, q, dt);
  }
  s.time += dt;
  ++s.step;
}

}  // namespace

template <int Dim>
void step_stencil(State<Dim>& s, double dt) {
  auto& g = s.grid;
  auto& p = s.particles;
  auto& clock = s.phases;
  clock.start();
  (*s.shape)(g, p, s.stencil);  // nearest nodes afresh, S_ip, G_ip
  clock.lap(Phase::stencil);
  p2g(p, s.stencil, s.small_strain, g, s.threads);  // m_i, v_i^n (eq. 3.16), f_i
  if (s.manufactured) s.tallies.body_work += dt * s.manufactured->add_body_force(p, s.stencil, s.time, g);
  clock.lap(Phase::p2g);
  const bool distribute = s.mass_distribution.on;
  if (distribute) distribute_small_mass_forces(g, s.mass_distribution.threshold, s.mass_distribution.maps, s.threads);  // eqs. 7.4-7.6
  solve_grid(g, s.boundary, s.time, dt, s.tallies, s.threads);  // v^L (eq. 3.12) with boundaries
  if (distribute) gradient_velocities(g, s.mass_distribution.maps, midpoint_weights(s.midpoint_gradient), s.threads);  // eq. 7.7
  clock.lap(Phase::grid);
  s.finite_check = g2p(g, s.stencil, dt, s.move, s.midpoint_gradient, p, s.threads);  // v_p, x_p, grad v
  if (s.musl)
    musl_gradient(s.stencil, s.boundary, s.time + dt, g, p, distribute ? &s.mass_distribution.maps : nullptr,
                  s.musl_velocity, s.threads);
  clock.lap(Phase::g2p);
  finish(s, dt);
  clock.lap(Phase::material);
}

namespace {

template <int Dim>
void step_body(State<Dim>& s, double dt) {
  if constexpr (Dim > 1) {
    step_stencil(s, dt);
  } else {
    auto& g = s.grid;
    auto& p = s.particles;
    const SchemeOptions& opt = s.shape->options();
    const Scheme scheme = opt.scheme;
    if ((scheme != Scheme::mpm && scheme != Scheme::ddmp && scheme != Scheme::ddmp_subpoints) ||
        s.mass_distribution.on || s.tensor_viscosity.on || s.musl)
      return step_stencil(s, dt);
    // Fused hat + transfers (mpm; DDMP, eq. 3.31, sub-points eqs. 6.1-6.3): the same
    // algorithm as the stencil path. For a linear elastic solid without viscosity, g2p
    // also does what finish() does, in its own pass, where it can: the law supplies the
    // form the kernels take (material.hpp, fused_elastic).
    shape::ElasticUpdate update;
    const material::FusedElastic1d* law = s.viscosity <= 0.0 ? s.material->fused_elastic() : nullptr;
    const bool elastic = law != nullptr;
    if (elastic) {
      update.small_strain = s.small_strain;
      update.youngs_modulus = law->youngs_modulus;
    }
    shape::ElasticUpdate* fuse = elastic ? &update : nullptr;
    if (scheme == Scheme::mpm) {
      shape::p2g_linear(g, p, s.small_strain, s.viscosity <= 0.0, s.linear_cells, g);
      solve_grid(g, s.boundary, s.time, dt, s.tallies);
      s.finite_check = shape::g2p_linear(g, s.linear_cells, dt, s.move, s.midpoint_gradient, p, fuse);
    } else {
      const int sub = scheme == Scheme::ddmp ? 0 : opt.subpoints;
      shape::p2g_ddmp(g, p, s.small_strain, sub, s.linear_cells, g);
      solve_grid(g, s.boundary, s.time, dt, s.tallies);
      s.finite_check = shape::g2p_ddmp(g, s.linear_cells, dt, s.move, s.midpoint_gradient, sub, p, fuse);
    }
    if (update.done) {
      s.tallies.stress_work += update.stress_work;
      s.time += dt;
      ++s.step;
      return;
    }
    finish(s, dt);
  }
}

}  // namespace

template <int Dim>
void step(State<Dim>& s, double dt) {
  try {
    // A piston carries the grid (piston_grid.hpp): the step's at t, and between steps
    // where the outputs read it, at the new time.
    const bool carried = has_piston(s.boundary);
    if (carried) carry_grid(s.grid, s.boundary, s.time);
    step_body(s, dt);
    if (carried) carry_grid(s.grid, s.boundary, s.time);
  } catch (const RunError& e) {
    // A point past the grid, a law's failure (a Mie-Gruneisen point past its Hugoniot's
    // limit, an MD box): thrown before the clock moves, so this step, from this time.
    throw RunError(fmt::format("{} in step {} (t = {:.6g})", e.what(), s.step + 1, s.time));
  }
}

template void step_stencil<1>(State<1>&, double);
template void step_stencil<2>(State<2>&, double);
template void step_stencil<3>(State<3>&, double);
template void step<1>(State<1>&, double);
template void step<2>(State<2>&, double);
template void step<3>(State<3>&, double);

}  // namespace mpmx::mpm
