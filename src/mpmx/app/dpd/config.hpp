#pragma once
// The DPD deck (`mpmx dpd DECK`): potential, domain, particle blocks, rigid groups, the
// DPD(E) parameters, an optional Berendsen equilibration and the run, read with every
// error named (key, value, reason). docs/guide.md lists the keys.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "mpmx/app/dpd/analysis.hpp"
#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/dpd/thermostat.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/multiscale/dpd_mpm.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

// A block of particles: an fcc lattice or a uniform random fill.
struct BlockSpec {
  bool fcc = true;
  std::array<int, 3> cells{1, 1, 1};  // fcc
  double constant = 0;                // fcc lattice constant, Angstrom
  long count = 0;                     // random
  particles::Vec3 size{};                    // random: extent, Angstrom
  particles::Vec3 origin{};
  double mass = 0;                    // amu
  particles::Vec3 velocity{};                // Angstrom/ps, added to the thermal velocities
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
  particles::Vec3 velocity{};
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
  multiscale::GridSpec grid;
  multiscale::ContinuumSpec continuum;
  std::string deck_file;
  // `mpmx dpd --still`: the run's rigid groups (flyer, grips) start at rest instead of at
  // their velocity, all else the same: the twin whose tracks, subtracted from the driven
  // run's, leave the response to the drive alone (the same random streams, so the two
  // agree to round-off until the drive's wave arrives).
  bool still = false;
};

// The deck's [potential]: a pair potential's `style` and parameters
// (potential/registry.hpp), or `file`: a potential file (a TOML [potential] table, as
// `mpmx fit-dpd` writes) found as given or in `deck_dir`; errors are recorded in the deck.
PairPotential read_potential(io::Section s, const std::string& deck_dir = "");

// Reads and validates; throws InputError listing every problem (Deck::finish()).
DpdConfig read_dpd_config(io::Deck& deck);

}  // namespace mpmx::app::dpd
