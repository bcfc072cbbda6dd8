#include "mpmx/multiscale/dpd_mpm.hpp"

#include <algorithm>
#include <limits>

#include "mpmx/core/units.hpp"
#include "mpmx/dpd/elastic.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/material/cubic_elastic.hpp"
#include "mpmx/multiscale/dpd_grid.hpp"

namespace mpmx::multiscale {

dpd::MoverFactory dpd_mpm_mover(const GridSpec& grid_spec, const ContinuumSpec& continuum,
                                const dpd::PairPotential& potential, int threads) {
  if (!(grid_spec.cell > 0)) return {};
  return [grid_spec, continuum, potential, threads](dpd::System& sys) -> std::unique_ptr<dpd::Mover> {
    const dpd::Particles& p = sys.particles();
    particles::Vec3 lo{}, hi{};
    for (int d = 0; d < 3; ++d) lo[d] = std::numeric_limits<double>::infinity(), hi[d] = -lo[d];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double x[3] = {p.x[i], p.y[i], p.z[i]};
      for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
    }
    for (int d = 0; d < 3; ++d) lo[d] -= grid_spec.margin, hi[d] += grid_spec.margin + 1e-9;
    auto grid = std::make_unique<DpdGrid>(grid_spec.cell, lo, hi, threads);
    if (continuum.on) {
      material::CubicConstants k;
      if (continuum.from_potential) {
        const dpd::LatticeConstants b = dpd::fcc_born_constants(potential, continuum.lattice_constant);
        k.c11 = b.c11, k.c12 = b.c12, k.c44 = b.c44;
      } else {
        k.c11 = continuum.c11 / units::eV_per_A3_in_GPa;
        k.c12 = continuum.c12 / units::eV_per_A3_in_GPa;
        k.c44 = continuum.c44 / units::eV_per_A3_in_GPa;
      }
      const int group = sys.group_index(kContinuumGroup);
      const double a = continuum.lattice_constant;
      grid->set_pair_reaction(continuum.pair_reaction);
      grid->set_continuum(group, std::make_unique<material::CubicElastic<3>>(k), p, a * a * a / 4.0);
      grid->set_constants_gpa(k.c11 * units::eV_per_A3_in_GPa, k.c12 * units::eV_per_A3_in_GPa,
                              k.c44 * units::eV_per_A3_in_GPa);
    }
    return grid;
  };
}

}  // namespace mpmx::multiscale
