#pragma once
// The mover of a DPD deck with [grid] (and [continuum]): the DPD/MPM grid over the
// particles' extent at the run's start plus the margin, and, for a concurrent run, the
// continuum points' cubic elastic law with the DPD model's constants (dpd/elastic.hpp).
#include "mpmx/dpd/mover.hpp"
#include "mpmx/dpd/potential/registry.hpp"

namespace mpmx::multiscale {

// [grid]: the DPD/MPM-grid model (seed 004 sec. 3.2) when cell > 0; DPD-only otherwise.
struct GridSpec {
  double cell = 0;     // Angstrom
  double margin = 30;  // Angstrom around the particles' extent at the run's start
};

// [continuum]: the concurrent DPD/MPM model (sec. 4.2, eq. 3.1). The mobile particles
// whose x at the run's start lies in [lo, hi) become material points of a cubic elastic
// continuum with the DPD model's constants (Born sums at lattice_constant) or given ones.
struct ContinuumSpec {
  bool on = false;
  double lo = 0, hi = 0;          // Angstrom
  double lattice_constant = 0;    // Angstrom: volume per point a^3/4, and the Born sums
  bool from_potential = true;     // constants_from = "pair_potential"
  double c11 = 0, c12 = 0, c44 = 0;  // GPa, when given
  bool pair_reaction = true;      // interface = "pair_reaction" (default) or "seed" (eq. 3.1 as written)
};

// The external group of a concurrent run's continuum points (the run adds it).
inline constexpr const char* kContinuumGroup = "continuum";

// Empty for a DPD-only deck (grid.cell 0).
dpd::MoverFactory dpd_mpm_mover(const GridSpec& grid, const ContinuumSpec& continuum,
                                const dpd::PairPotential& potential, int threads);

}  // namespace mpmx::multiscale
