#pragma once
// A constitutive closure works on the whole batch of material points at once, so that
// a costly closure (an MD system per point) can spread the batch over threads without
// the solver knowing. Called once per step, never per particle.
#include <cmath>
#include <iosfwd>
#include <memory>
#include <string>

#include "mpmx/mpm/particles.hpp"

namespace mpmx::material {

template <int Dim>
class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  // Sets the initial stress (and any per-point state) from the initial fields.
  virtual void initialize(mpm::Particles<Dim>& p) = 0;
  // Stress at t^{n+1} from the velocity gradient grad_v (eq. 4.10) and the updated
  // volume; dt is the continuum step. A closure may keep per-point state (md_closure).
  virtual void update_stress(mpm::Particles<Dim>& p, double dt) = 0;
  // Longitudinal sound speed of point q (for the CFL limit and artificial viscosity).
  virtual double sound_speed(const mpm::Particles<Dim>& p, std::size_t q) const = 0;
  // Per-point state beyond the particle arrays, for checkpoints (none by default).
  virtual void save(std::ostream&) const {}
  virtual void load(std::istream&) {}
};

}  // namespace mpmx::material
