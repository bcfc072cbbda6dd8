#include "mpmx/particles/tile_planes.hpp"

#include <algorithm>

namespace mpmx::particles {

TilePlanes tile_planes(const LatticeSpec& spec) {
  TilePlanes p;
  if (spec.plain_fcc()) {
    const double a = spec.constant;
    p.length = {a, a, a};
    p.end_gap = {0.5 * a, 0.5 * a, 0.5 * a};
    p.x_planes = {0.0, 0.5};
    p.atoms = 4;
    return p;
  }
  const LatticeTile tile = lattice_tile(spec);
  p.length = tile.length;
  p.atoms = tile.atoms;
  std::array<double, 3> last{0, 0, 0};
  for (const auto& f : tile.sites) {
    for (int d = 0; d < 3; ++d) last[d] = std::max(last[d], f[d]);
    p.x_planes.push_back(f[0]);
  }
  for (int d = 0; d < 3; ++d) p.end_gap[d] = (1.0 - last[d]) * tile.length[d];
  // The sites' fractions are exact to 1e-9 (lattice_tile rounds whole numbers); one plane
  // per distinct value.
  std::sort(p.x_planes.begin(), p.x_planes.end());
  p.x_planes.erase(std::unique(p.x_planes.begin(), p.x_planes.end(),
                               [](double u, double v) { return v - u < 1e-9; }),
                   p.x_planes.end());
  return p;
}

}  // namespace mpmx::particles
