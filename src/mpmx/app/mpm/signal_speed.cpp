#include "mpmx/app/mpm/signal_speed.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/mpm/boundary_speed.hpp"

namespace mpmx::app {

using mpm::BoundarySide;

double smallest_cell(const MpmConfig& c) {
  double dx = c.dx();
  for (int d = 1; d < c.dim; ++d) dx = std::min(dx, (c.upper_all[d] - c.lower_all[d]) / c.cells_all[d]);
  return dx;
}

double initial_signal_speed(const MpmConfig& c) {
  const int dim = c.dim;
  const auto& mat = c.material;
  if (!(c.upper > c.lower && c.cells >= 1 && mat.density > 0.0 && mat.spec)) return 0.0;
  double pmax = 0.0;  // the largest pressure of a gas's initial profile
  const double L = c.upper - c.lower;
  if (!mat.solid())
    for (int i = 0; i <= 4 * c.cells; ++i)
      pmax = std::max(pmax, c.pressure(c.lower + L * i / (4.0 * c.cells), c.lower, L, c.dx()));
  double cs_max = mat.spec->wave_speed(dim, mat.density, pmax);
  for (const auto& body : c.bodies)
    if (body.material) cs_max = std::max(cs_max, body.material->wave_speed(dim, body.material->density(), pmax));
  return cs_max + fastest_drive(c);
}

double fastest_drive(const MpmConfig& c) {
  const int dim = c.dim;
  // A body's fastest point: its velocity plus its spin times its radius (|omega| r_max).
  double vmax = 0.0;
  for (const auto& body : c.bodies) {
    double v2 = 0.0;
    for (int d = 0; d < dim; ++d) v2 += body.velocity[d] * body.velocity[d];
    vmax = std::max(vmax, std::sqrt(v2) + std::abs(body.angular_velocity) * body.radius);
  }
  // A piston moves its nodes at its speed: any of its table's, the whole run's.
  for (int f = 0; f < 2 * dim; ++f)
    if (c.boundary.face[f].type == BoundarySide::Type::piston)
      for (double v : c.boundary.face[f].piston.speeds) vmax = std::max(vmax, std::abs(v));
  return std::max(vmax, mpm::boundary_speed(c.boundary, dim, 0.0, 0.0));  // a velocity face's
}

double time_quantum(const MpmConfig& c) {
  double q = c.material.spec ? c.material.spec->time_quantum() : 0.0;
  for (const auto& body : c.bodies)
    if (body.material) q = std::max(q, body.material->time_quantum());
  return q;
}

double whole_quanta(double dt, double quantum) {
  if (!(quantum > 0.0)) return dt;
  return std::max(1.0, std::floor(dt / quantum * (1.0 + 1e-12))) * quantum;
}

double first_cfl_step(const MpmConfig& c) {
  return whole_quanta(c.cfl * smallest_cell(c) / initial_signal_speed(c), time_quantum(c));
}

}  // namespace mpmx::app
