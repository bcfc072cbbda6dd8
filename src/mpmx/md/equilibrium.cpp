#include "mpmx/md/equilibrium.hpp"

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::md {

namespace {

// The crystal at lattice constant a under an engineering strain along x.
using Builder = std::function<Crystal(double a, double strain_x)>;

// A perfect lattice: energy and stress are the same for any cell count the list
// handles, so a small box does (own images are ghosts like any other).
System crystal(const Builder& build, const Potential& pot, double a, double strain_x = 0.0) {
  return System(build(a, strain_x), pot);
}

// The same crystal under the simple shear x += gamma y (atoms and image lattice): the
// homogeneous shear (no internal relaxation: exact for a Bravais lattice).
System sheared(const Builder& build, const Potential& pot, double a, double gamma) {
  Crystal c = build(a, 0.0);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    double& x = c.atoms.x[i];
    x += gamma * c.atoms.y[i];
    x -= c.box.lx * std::floor(x / c.box.lx);
  }
  c.box.xy = gamma * c.box.ly;
  return System(c, pot);
}

double pressure(const Builder& build, const Potential& pot, double a) {
  const Mat3 s = crystal(build, pot, a).stress();
  return -(s[0] + s[4] + s[8]) / 3.0;
}

// Coarse energy scan of a in [lo, hi] for the bracket, then bisection on the pressure,
// which is linear through the minimum (the energy is flat there, the pressure is not).
FccEquilibrium equilibrium(const Builder& build, const Potential& pot, double lo, double hi, const char* name) {
  const int n = 200;
  double best_a = 0, best_e = INFINITY;
  for (int k = 0; k <= n; ++k) {
    const double a = lo + (hi - lo) * k / n;
    const System s = crystal(build, pot, a);
    const double e = s.potential_energy() / static_cast<double>(s.atoms().size());
    if (e < best_e) best_e = e, best_a = a;
  }
  const double h = (hi - lo) / n;
  double a0 = best_a - h, a1 = best_a + h;
  double p0 = pressure(build, pot, a0), p1 = pressure(build, pot, a1);
  if (!(best_a > lo && best_a < hi) || !(p0 > 0 && p1 < 0))
    throw RunError(fmt::format("no {} energy minimum of the potential between {} and {} Angstrom", name, lo, hi));
  for (int it = 0; it < 200 && a1 - a0 > 1e-14 * a1; ++it) {
    const double am = 0.5 * (a0 + a1), pm = pressure(build, pot, am);
    if (pm > 0) a0 = am, p0 = pm;
    else a1 = am, p1 = pm;
  }
  FccEquilibrium r;
  r.lattice_constant = std::abs(p0) < std::abs(p1) ? a0 : a1;
  const System s = crystal(build, pot, r.lattice_constant);
  r.energy_per_atom = s.potential_energy() / static_cast<double>(s.atoms().size());
  const double e = 1e-5;  // central difference: O(e^2) error, far below the digits used
  const double a = r.lattice_constant;
  r.c11_gpa = (crystal(build, pot, a, e).stress_gpa()[0] - crystal(build, pot, a, -e).stress_gpa()[0]) / (2 * e);
  r.c12_gpa = (crystal(build, pot, a, e).stress_gpa()[4] - crystal(build, pot, a, -e).stress_gpa()[4]) / (2 * e);
  r.c44_gpa = (sheared(build, pot, a, e).stress_gpa()[1] - sheared(build, pot, a, -e).stress_gpa()[1]) / (2 * e);
  double mass = 0;
  for (const int t : s.atoms().type) mass += pot.mass(t);
  r.density_amu_per_A3 = mass / s.box().volume();
  return r;
}

}  // namespace

FccEquilibrium fcc_equilibrium(const Potential& pot) {
  const Builder build = [](double a, double strain_x) { return fcc(2, 2, 2, a, strain_x); };
  FccEquilibrium r = equilibrium(build, pot, 0.5 * pot.cutoff(), 3.0 * pot.cutoff(), "fcc");
  r.density_amu_per_A3 = 4.0 * pot.mass(0) / std::pow(r.lattice_constant, 3);  // as it always was
  return r;
}

std::array<int, 3> equilibrium_tiles(const particles::LatticeSpec& shape) {
  particles::LatticeSpec unit = shape;
  unit.constant = 1.0;
  const particles::LatticeTile t = particles::lattice_tile(unit);
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d) n[d] = std::max(1, static_cast<int>(std::ceil(2.0 / t.length[d] - 1e-9)));
  return n;
}

CrystalEquilibrium lattice_equilibrium(const Potential& pot, const particles::LatticeSpec& shape) {
  if (shape.plain_fcc()) return fcc_equilibrium(pot);
  const std::array<int, 3> tiles = equilibrium_tiles(shape);
  const Builder build = [&shape, tiles](double a, double strain_x) {
    particles::LatticeSpec s = shape;
    s.constant = a;
    return particles::oriented_crystal(s, tiles, strain_x);
  };
  // Nearest neighbours from a quarter of the cutoff (W_zhou's bcc W: 0.35 of its 7.9 A) to
  // twice it: fcc's scan (a from 0.5 to 3 cutoffs, 0.35 to 2.1 in neighbours) widened.
  const double to_a = 1.0 / particles::nearest_neighbour_ratio(shape);
  return equilibrium(build, pot, 0.25 * to_a * pot.cutoff(), 2.0 * to_a * pot.cutoff(),
                     particles::lattice_name(shape.style));
}

}  // namespace mpmx::md
