#pragma once
// The DPD deck (`mpmx dpd DECK`): potential, domain, particle blocks, rigid groups, the
// DPD(E) parameters, an optional Berendsen equilibration and the run, read with every
// error named (key, value, reason). docs/guide.md lists the keys.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "mpmx/dpd/analysis.hpp"
#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/dpd/thermostat.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::dpd {

// A block of particles: an fcc lattice or a uniform random fill.
struct BlockSpec {
  bool fcc = true;
  std::array<int, 3> cells{1, 1, 1};  // fcc
  double constant = 0;                // fcc lattice constant, Angstrom
  long count = 0;                     // random
  md::Vec3 size{};                    // random: extent, Angstrom
  md::Vec3 origin{};
  double mass = 0;                    // amu
  md::Vec3 velocity{};                // Angstrom/ps, added to the thermal velocities
  std::string group;                  // rigid group name ("" mobile)
  bool free = false;                  // the group is a free rigid body from `velocity` (the run only)
};

// A rigid group by region (the tensile grips): particles with lo <= x < hi on each axis.
struct RegionGroupSpec {
  std::string name;
  std::array<double, 3> lo{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()};
  std::array<double, 3> hi{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::infinity()};
  md::Vec3 velocity{};
};

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

struct DpdConfig {
  std::string id, title, seed_ref;
  PairPotential potential;
  Domain domain;
  std::vector<BlockSpec> blocks;
  std::vector<RegionGroupSpec> regions;
  DpdParams params;
  double initial_temperature = 0;  // K: Maxwell velocities (and DPDE internal temperature)
  bool equilibrate = false;
  Berendsen berendsen;
  std::int64_t equilibrate_steps = 0;
  double dt = 0.001;  // ps
  std::int64_t steps = 0;
  std::int64_t thermo = 100;
  std::int64_t dump_every = 0;
  double skin = 1.0;
  AnalysisSpec analysis;
  GridSpec grid;
  ContinuumSpec continuum;
  std::string deck_file;
  // `mpmx dpd --still`: the run's rigid groups (flyer, grips) start at rest instead of at
  // their velocity, all else the same: the twin whose tracks, subtracted from the driven
  // run's, leave the response to the drive alone (the same random streams, so the two
  // agree to round-off until the drive's wave arrives).
  bool still = false;
};

// Reads and validates; throws InputError listing every problem (Deck::finish()).
DpdConfig read_dpd_config(io::Deck& deck);

}  // namespace mpmx::dpd
