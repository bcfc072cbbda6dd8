#include "mpmx/md/bar.hpp"

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/stress.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::md {

System Bar::build(const BarConfig& c, Potential pot, SystemOptions o) {
  if (c.cells_x < 2 || c.cells_yz < 1 || c.bins < 1 || !(c.split > 0 && c.split < 1) ||
      !(c.strain_left > -0.5 && c.strain_left < 0.5))
    throw InputError(fmt::format("bar: cells_x {} (>= 2), cells_yz {} (>= 1), bins {} (>= 1), split {} in "
                                 "(0,1), strain_left {} in (-0.5,0.5)",
                                 c.cells_x, c.cells_yz, c.bins, c.split, c.strain_left));
  particles::LatticeSpec lat = c.lattice;
  lat.constant = c.lattice_constant;
  Crystal cr = particles::oriented_crystal(lat, {c.cells_x, c.cells_yz, c.cells_yz});
  const double a = c.lattice_constant, length = lat.plain_fcc() ? c.cells_x * a : cr.box.lx;
  // From the last atomic plane to the bar's periodic length: fcc's a / 2, or the tile's.
  const double end_space = particles::tile_planes(lat).end_gap[0];
  const double xs = c.split * length, gap = 2.0 * (pot.cutoff() + o.skin) + a;
  for (auto& x : cr.atoms.x) {
    // Strain the left part (x and its length times 1 + e), shift the rest with it.
    x = x < xs ? x * (1 + c.strain_left) : x + xs * c.strain_left;
    x += 0.5 * gap;
  }
  const double strained = length + xs * c.strain_left;
  cr.box.lx = strained + gap;  // vacuum beyond the walls: no interaction across x
  o.per_atom = true;
  System s(cr, std::move(pot), o);
  if (c.temperature > 0) s.thermalize(c.temperature, c.seed, 0);
  // Walls on the end planes (a hair outside): an end plane pushed outward is mirrored
  // at once, as at a fixed continuum boundary. Half a plane spacing out instead, a
  // compressed end plane first flies free, hits the wall and sends a tensile pulse
  // into the bar (-0.9 GPa behind a -9 GPa state, e0 = -5%).
  Walls w;
  w.enabled = true;
  const double hair = 1e-6;  // Angstrom
  w.lo = 0.5 * gap - hair;
  w.hi = 0.5 * gap + strained - end_space + hair;
  w.v_lo = c.piston_velocity;
  s.set_walls(w);
  return s;
}

Bar::Bar(const BarConfig& config, Potential potential, SystemOptions options)
    : cfg_(config), sys_(build(config, std::move(potential), options)) {}

std::vector<Mat3> Bar::slab_stress_gpa() const {
  const Walls& w = sys_.walls();
  // refresh per-atom virial of the current step is kept by the System (per_atom).
  auto s = slab_stress(sys_.snapshot(), sys_.type_mass(), sys_.per_atom_virial(), sys_.box(), cfg_.bins, w.lo,
                       w.hi);
  for (auto& m : s)
    for (auto& v : m) v *= units::eV_per_A3_in_GPa;
  return s;
}

std::vector<double> Bar::slab_centres() const {
  const Walls& w = sys_.walls();
  std::vector<double> c;
  for (int b = 0; b < cfg_.bins; ++b) c.push_back(w.lo + (b + 0.5) * (w.hi - w.lo) / cfg_.bins);
  return c;
}

}  // namespace mpmx::md
