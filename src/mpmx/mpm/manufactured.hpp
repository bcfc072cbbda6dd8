#pragma once
// A run driven by the manufactured solution of reference/manufactured.hpp (VALIDATION.md
// N4): each step the body force b(X_p, t^n) joins the internal force at the nodes as
// sum_p m_p b_p S_ip, and the error is each point's displacement x_p - X_p against
// u(X_p, t). The material coordinates X_p are the points' initial positions (points keep
// their order for the whole run).
#include <array>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/reference/manufactured.hpp"
#include "mpmx/reference/norms.hpp"

namespace mpmx::mpm {

template <int Dim>
class Manufactured {
 public:
  // Takes X_p from the points as set up; the solution's parameters (checked).
  Manufactured(const reference::AxisAligned& solution, const Particles<Dim>& initial);

  // The exact velocity at t = 0.
  void start(Particles<Dim>& p) const;
  // Adds sum_p m_p b(X_p, t) S_ip to the nodal forces; returns the force's power on the
  // points, sum_p m_p b . v_p (the energy account's body work, with the step's dt).
  double add_body_force(const Particles<Dim>& p, const Stencil<Dim>& st, double t, Grid<Dim>& g) const;
  // |x_p - X_p - u(X_p, t)| over the points, volume-weighted, relative to the amplitude.
  reference::ErrorNorms displacement_error(const Particles<Dim>& p, double t) const;

 private:
  reference::AxisAligned m_;
  std::array<std::vector<double>, Dim> X_;
};

}  // namespace mpmx::mpm
