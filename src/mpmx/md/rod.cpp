#include "mpmx/md/rod.hpp"

#include <numeric>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::md {

System build_rod(const RodConfig& c, Potential pot, SystemOptions o, RodGeometry* geometry) {
  const int nf = c.flyer_cells, nx = c.target_cells[0], ny = c.target_cells[1], nz = c.target_cells[2];
  const double a = c.lattice_constant;
  if (nf < 1 || nx < 1 || ny < 1 || nz < 1 || !(a > 0))
    throw InputError(fmt::format("rod: flyer {} tiles, target {} x {} x {} tiles, lattice constant {} A: needs at "
                                 "least one tile each and a positive constant",
                                 nf, nx, ny, nz, a));
  particles::LatticeSpec lat = c.lattice;
  lat.constant = a;
  if (lat.style == particles::LatticeStyle::b2)
    throw InputError("rod: a b2 lattice holds two elements; the rod is of one (its momentum is a plain mean)");
  const particles::TilePlanes t = particles::tile_planes(lat);
  const Crystal cr = particles::oriented_crystal(lat, {nf + nx, ny, nz});
  const double reach = pot.cutoff() + o.skin;
  const double span = (nf + nx) * t.length[0];
  const Vec3 offset{reach + 0.5 * span, reach + t.length[1], reach + t.length[2]};
  // Flyer and target part half way between the flyer's last plane and the target's first.
  const double split = nf * t.length[0] - 0.5 * t.end_gap[0];
  Atoms flyer, target;
  for (std::size_t i = 0; i < cr.atoms.size(); ++i) {
    const double x = cr.atoms.x[i], y = cr.atoms.y[i], z = cr.atoms.z[i];
    (x < split ? flyer : target).push_back(x + offset[0], y + offset[1], z + offset[2], 0, 0);
  }
  Atoms all = flyer;
  for (std::size_t i = 0; i < target.size(); ++i) all.push_back(target.x[i], target.y[i], target.z[i], 0, 0);
  std::iota(all.id.begin(), all.id.end(), std::int64_t{1});
  Box box;
  box.lx = span + 2.0 * offset[0];
  box.ly = ny * t.length[1] + 2.0 * offset[1];
  box.lz = nz * t.length[2] + 2.0 * offset[2];
  System s(all, box, std::move(pot), o);
  const std::int64_t nfa = static_cast<std::int64_t>(flyer.size());
  if (c.temperature > 0) {
    s.thermalize(c.temperature, c.seed, 0);
    Atoms& at = s.edit_atoms();
    double m[3] = {0, 0, 0};  // one type: the mass-weighted mean is the plain mean
    for (std::size_t i = 0; i < at.size(); ++i)
      if (at.id[i] > nfa) m[0] += at.vx[i], m[1] += at.vy[i], m[2] += at.vz[i];
    for (double& v : m) v /= static_cast<double>(target.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
      if (at.id[i] <= nfa) {
        at.vx[i] = at.vy[i] = at.vz[i] = 0.0;
      } else {
        at.vx[i] -= m[0], at.vy[i] -= m[1], at.vz[i] -= m[2];
      }
    }
    s.rescale_temperature(2.0 * c.temperature, nfa);  // the target at rest, at 2T
  }
  s.set_frozen_ids(nfa);
  s.refresh();
  if (geometry) {
    geometry->offset = offset;
    geometry->impact_face = nf * t.length[0];
    geometry->length = nx * t.length[0];
    geometry->ly = ny * t.length[1];
    geometry->lz = nz * t.length[2];
    geometry->flyer_atoms = nfa;
  }
  return s;
}

}  // namespace mpmx::md
