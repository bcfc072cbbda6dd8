#include "mpmx/md/equilibrium.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::md {

namespace {

// A perfect lattice: energy and stress are the same for any cell count the list
// handles, so a small box does (own images are ghosts like any other).
System crystal(const Potential& pot, double a, double strain_x = 0.0) {
  return System(fcc(2, 2, 2, a, strain_x), pot);
}

// The same crystal under the simple shear x += gamma y (atoms and image lattice). fcc is
// a Bravais lattice: no internal relaxation, so the homogeneous shear is the answer.
System sheared(const Potential& pot, double a, double gamma) {
  Crystal c = fcc(2, 2, 2, a);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    double& x = c.atoms.x[i];
    x += gamma * c.atoms.y[i];
    x -= c.box.lx * std::floor(x / c.box.lx);
  }
  c.box.xy = gamma * c.box.ly;
  return System(c, pot);
}

double pressure(const Potential& pot, double a) {
  const Mat3 s = crystal(pot, a).stress();
  return -(s[0] + s[4] + s[8]) / 3.0;
}

}  // namespace

FccEquilibrium fcc_equilibrium(const Potential& pot) {
  // Coarse energy scan for the bracket, then bisection on the pressure, which is
  // linear through the minimum (the energy is flat there, the pressure is not).
  const double lo = 0.5 * pot.cutoff(), hi = 3.0 * pot.cutoff();
  const int n = 200;
  double best_a = 0, best_e = INFINITY;
  for (int k = 0; k <= n; ++k) {
    const double a = lo + (hi - lo) * k / n;
    const System s = crystal(pot, a);
    const double e = s.potential_energy() / static_cast<double>(s.atoms().size());
    if (e < best_e) best_e = e, best_a = a;
  }
  const double h = (hi - lo) / n;
  double a0 = best_a - h, a1 = best_a + h;
  double p0 = pressure(pot, a0), p1 = pressure(pot, a1);
  if (!(best_a > lo && best_a < hi) || !(p0 > 0 && p1 < 0))
    throw RunError(fmt::format("no fcc energy minimum of the potential between {} and {} Angstrom", lo, hi));
  for (int it = 0; it < 200 && a1 - a0 > 1e-14 * a1; ++it) {
    const double am = 0.5 * (a0 + a1), pm = pressure(pot, am);
    if (pm > 0) a0 = am, p0 = pm;
    else a1 = am, p1 = pm;
  }
  FccEquilibrium r;
  r.lattice_constant = std::abs(p0) < std::abs(p1) ? a0 : a1;
  const System s = crystal(pot, r.lattice_constant);
  r.energy_per_atom = s.potential_energy() / static_cast<double>(s.atoms().size());
  const double e = 1e-5;  // central difference: O(e^2) error, far below the digits used
  r.c11_gpa = (crystal(pot, r.lattice_constant, e).stress_gpa()[0] -
               crystal(pot, r.lattice_constant, -e).stress_gpa()[0]) / (2 * e);
  r.c12_gpa = (crystal(pot, r.lattice_constant, e).stress_gpa()[4] -
               crystal(pot, r.lattice_constant, -e).stress_gpa()[4]) / (2 * e);
  r.c44_gpa = (sheared(pot, r.lattice_constant, e).stress_gpa()[1] -
               sheared(pot, r.lattice_constant, -e).stress_gpa()[1]) / (2 * e);
  r.density_amu_per_A3 = 4.0 * pot.mass(0) / std::pow(r.lattice_constant, 3);
  return r;
}

}  // namespace mpmx::md
