#include "mpmx/app/mpm/step_notes.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "mpmx/app/mpm/signal_speed.hpp"
#include "mpmx/mpm/tensor_viscosity.hpp"

namespace mpmx::app {

std::vector<std::string> describe_time_step(const MpmConfig& c) {
  std::vector<std::string> lines;
  const double h = smallest_cell(c), speed = initial_signal_speed(c), drive = fastest_drive(c);
  const double quantum = time_quantum(c);
  if (!(speed > 0.0) || !(h > 0.0)) return lines;
  const double start = c.cfl_dt ? c.cfl * h / speed : c.cfl_limit * h / speed;
  const std::string whole =
      quantum > 0.0 ? fmt::format(", in whole MD steps of {:.6g}", quantum) : std::string();
  if (c.cfl_dt)
    lines.push_back(fmt::format(
        "time step: dt = \"cfl\" at cfl = {:.3g}: the first {:.6g} ({:.3g} x h {:.6g} / (c + v) {:.6g}{}), each next "
        "from the state: c each point's wave speed at its current compression, the viscosity's explicit limit, at "
        "most max_volume_strain = {:.3g} of a point's volume a step, landing on every record time",
        c.cfl, c.dt, c.cfl, h, speed, whole, c.max_volume_strain));
  else
    lines.push_back(fmt::format("time step: dt = {:.6g} fixed; the start allows cfl_limit {:.3g} x h {:.6g} / (c + v) "
                                "{:.6g} = {:.6g} (Courant number {:.3f} at the start)",
                                c.dt, c.cfl_limit, h, speed, start, c.dt * speed / h));
  if (!(drive > 0.0)) return lines;
  // Each law once: the deck's and the bodies' own.
  std::set<const material::Model*> laws;
  if (c.material.spec) laws.insert(c.material.spec.get());
  for (const auto& body : c.bodies)
    if (body.material) laws.insert(body.material.get());
  // A fixed dt against the grid's own explicit limit too: with lumped nodal masses a
  // square cell's highest mode (the checkerboard along its diagonal) is stable only for
  // Courant numbers below 1 / sqrt(dim) (theory.md, "The time step").
  const double courant = c.cfl_dt ? c.cfl : std::min(c.cfl_limit, 1.0 / std::sqrt(double(c.dim)));
  for (const material::Model* law : laws) {
    const material::Model::Shocked s = law->shocked(c.dim, drive);
    if (!s.from_hugoniot || !(s.wave_speed > 0.0)) continue;
    double limit = courant * h / (s.wave_speed + drive);
    lines.push_back(fmt::format("shocked: a planar shock at up = {:.4g} (the deck's fastest body or drive) takes {} "
                                "to J = V/V0 = {:.4f}, where its fastest wave is {:.4g}: the step there is at most "
                                "{:.3g} x h / (c + up) = {:.6g}{}",
                                drive, law->name(), s.J, s.wave_speed, courant, limit,
                                c.cfl_dt ? "" : " (the Courant number the smaller of cfl_limit and 1/sqrt(dim))"));
    // The viscosity at the front tightens it (step_limit.hpp): Q = nu / h with the front one
    // cell wide (a uniaxial gradient -up / h), l the points' spacing along x and the
    // viscosity's sound speed taken as the shocked wave speed (an upper bound).
    const double l = h / std::max(1, c.per_cell_all[0]);
    double Q = 0.0;
    if (c.tensor_viscosity)
      Q = mpm::tensor_viscosity_coefficient<1>(Eigen::Matrix<double, 1, 1>(-drive / h), l, s.wave_speed, c.c_L,
                                               c.c_q) / h;
    else if (c.viscosity > 0.0)
      Q = c.viscosity * s.wave_speed * l / h;  // the linear form's nu = coef a l
    if (Q > 0.0) {
      limit = courant * h / (drive + Q + std::sqrt(Q * Q + s.wave_speed * s.wave_speed));
      lines.push_back(fmt::format("with the {} viscosity at a front one cell wide (its speed Q = {:.4g}, points {:.4g} "
                                  "apart): at most {:.3g} x h / (up + Q + sqrt(Q^2 + c^2)) = {:.6g}",
                                  c.tensor_viscosity ? "tensor" : "linear", Q, l, courant, limit));
    }
    if (!c.cfl_dt && c.dt > limit)
      lines.push_back(fmt::format("warning: time.dt = {:.6g} exceeds that by {:.0f}% (Courant number {:.3f} in the "
                                  "shocked {}): the run may blow up at impact; a smaller dt, or dt = \"cfl\"",
                                  c.dt, 100.0 * (c.dt / limit - 1.0), c.dt * (s.wave_speed + drive) / h, law->name()));
    else if (!c.cfl_dt)
      lines.push_back(fmt::format("time.dt = {:.6g} is within it ({:.0f}% margin, Courant number {:.3f} there)", c.dt,
                                  100.0 * (1.0 - c.dt / limit), c.dt * (s.wave_speed + drive) / h));
  }
  return lines;
}

}  // namespace mpmx::app
