#include "mpmx/md/jet.hpp"

#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::md {

namespace {
int scaled(int n, double s) { return static_cast<int>(std::lround(n * s)); }
}  // namespace

int JetConfig::nx() const { return scaled(cells[0], scale); }
int JetConfig::ny() const { return scaled(cells[1], scale); }
int JetConfig::npiston() const { return scaled(piston_cells, scale); }

System build_jet(const JetConfig& c, Potential pot, SystemOptions o, JetGeometry* geometry) {
  const int nx = c.nx(), ny = c.ny(), nz = c.nz(), np = c.npiston();
  particles::LatticeSpec lat = c.lattice;
  lat.constant = c.lattice_constant;
  if (lat.style == particles::LatticeStyle::b2)
    throw InputError("jet: a b2 lattice holds two elements; the jet's block is of one (its momentum is a plain mean)");
  const particles::TilePlanes t = particles::tile_planes(lat);
  const double tx = t.length[0];
  const double length = nx * tx, ly = ny * t.length[1], depth = c.notch_depth_A();
  if (nx < 2 || ny < 1 || nz < 1 || np < 1 || np >= nx || !(depth >= 0) || depth >= (nx - np) * tx)
    throw InputError(fmt::format("jet at scale {}: {} x {} x {} tiles of {:.6g} x {:.6g} x {:.6g} A, piston {} tiles, "
                                 "notch {} A: needs at least 2 x 1 x 1 tiles, a piston of 1 tile or more shorter "
                                 "than the sample, and a notch shallower than the block ({} A)",
                                 c.scale, nx, ny, nz, t.length[0], t.length[1], t.length[2], np, depth,
                                 (nx - np) * tx));
  const Crystal cr = particles::oriented_crystal(lat, {nx, ny, nz});
  // Half the gap between planes across each tile's end (fcc along the axes: a quarter cell).
  const double hx = 0.5 * t.end_gap[0], hy = 0.5 * t.end_gap[1], hz = 0.5 * t.end_gap[2];
  const double reach = pot.cutoff() + o.skin;
  const double vacuum = 2.0 * reach + tx + 0.5 * length;
  const double x0 = 0.5 * (2.0 * reach + tx);  // the piston's first plane
  const double piston_face = np * tx - hx;  // between the last piston plane and the first block plane
  // The V notch: the right face x = length - hx (half a gap past the last plane) cut back
  // by depth at mid-height, to no depth at y = 0 and y = ly.
  auto in_notch = [&](double x, double y) {
    const double tip = 1.0 - std::abs(2.0 * y / ly - 1.0);  // 1 at mid-height, 0 at the edges
    return x > length - hx - depth * tip;
  };
  Atoms piston, block;
  for (std::size_t i = 0; i < cr.atoms.size(); ++i) {
    // Half a gap along y and z: no atomic plane on a bin edge (bins of whole tiles or
    // half cells), so round-off cannot move a plane between bins; the V stays symmetric.
    const double x = cr.atoms.x[i], y = cr.atoms.y[i] + hy, z = cr.atoms.z[i] + hz;
    if (x < piston_face) piston.push_back(x + x0, y, z, 0, 0);
    else if (!in_notch(x, y)) block.push_back(x + x0, y, z, 0, 0);
  }
  Atoms all = piston;
  for (std::size_t i = 0; i < block.size(); ++i) all.push_back(block.x[i], block.y[i], block.z[i], 0, 0);
  std::iota(all.id.begin(), all.id.end(), std::int64_t{1});
  Box box = cr.box;
  box.lx = length + vacuum;
  o.per_atom = true;
  System s(all, box, std::move(pot), o);
  if (c.temperature > 0) s.thermalize(c.temperature, c.seed, 0);
  // The piston at rest; the block about zero mean, then at -up (km/s = 10 A/ps).
  const std::int64_t npa = static_cast<std::int64_t>(piston.size());
  Atoms& at = s.edit_atoms();
  double m[3] = {0, 0, 0};
  std::int64_t nb = 0;
  for (std::size_t i = 0; i < at.size(); ++i)
    if (at.id[i] > npa) m[0] += at.vx[i], m[1] += at.vy[i], m[2] += at.vz[i], ++nb;
  for (double& v : m) v = nb > 0 ? v / static_cast<double>(nb) : 0.0;  // one type: mass-weighted = plain mean
  const double up = 10.0 * c.velocity_km_s;
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (at.id[i] <= npa) {
      at.vx[i] = at.vy[i] = at.vz[i] = 0.0;
    } else {
      at.vx[i] -= m[0] + up;
      at.vy[i] -= m[1];
      at.vz[i] -= m[2];
    }
  }
  s.set_frozen_ids(npa);
  s.refresh();
  if (geometry) {
    geometry->x0 = x0 - hx;
    geometry->length = length;
    geometry->piston_face = x0 + piston_face;
    geometry->notch_tip = x0 + length - hx - depth;
    geometry->ly = ly;
    geometry->lz = box.lz;
    geometry->piston_atoms = npa;
    geometry->lattice = lat;
    geometry->origin = {x0, hy, hz};
  }
  return s;
}

}  // namespace mpmx::md
