#include "mpmx/md/rod.hpp"

#include <numeric>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

System build_rod(const RodConfig& c, Potential pot, SystemOptions o, RodGeometry* geometry) {
  const int nf = c.flyer_cells, nx = c.target_cells[0], ny = c.target_cells[1], nz = c.target_cells[2];
  const double a = c.lattice_constant;
  if (nf < 1 || nx < 1 || ny < 1 || nz < 1 || !(a > 0))
    throw InputError(fmt::format("rod: flyer {} cells, target {} x {} x {} cells, lattice constant {} A: needs at "
                                 "least one cell each and a positive constant",
                                 nf, nx, ny, nz, a));
  const Crystal cr = fcc(nf + nx, ny, nz, a);
  const double reach = pot.cutoff() + o.skin;
  const double span = (nf + nx) * a;
  const Vec3 offset{reach + 0.5 * span, reach + a, reach + a};
  Atoms flyer, target;
  for (std::size_t i = 0; i < cr.atoms.size(); ++i) {
    const double x = cr.atoms.x[i], y = cr.atoms.y[i], z = cr.atoms.z[i];
    (x < nf * a - 0.25 * a ? flyer : target).push_back(x + offset[0], y + offset[1], z + offset[2], 0, 0);
  }
  Atoms all = flyer;
  for (std::size_t i = 0; i < target.size(); ++i) all.push_back(target.x[i], target.y[i], target.z[i], 0, 0);
  std::iota(all.id.begin(), all.id.end(), std::int64_t{1});
  Box box;
  box.lx = span + 2.0 * offset[0];
  box.ly = ny * a + 2.0 * offset[1];
  box.lz = nz * a + 2.0 * offset[2];
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
    geometry->impact_face = nf * a;
    geometry->length = nx * a;
    geometry->ly = ny * a;
    geometry->lz = nz * a;
    geometry->flyer_atoms = nfa;
  }
  return s;
}

}  // namespace mpmx::md
