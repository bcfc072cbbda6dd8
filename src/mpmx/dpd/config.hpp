#pragma once
// The DPD deck (`mpmx dpd DECK`): potential, domain, particle blocks, rigid groups, the
// DPD(E) parameters, an optional Berendsen equilibration and the run, read with every
// error named (key, value, reason). docs/guide.md lists the keys.
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

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
  std::string deck_file;
};

// Reads and validates; throws InputError listing every problem (Deck::finish()).
DpdConfig read_dpd_config(io::Deck& deck);

}  // namespace mpmx::dpd
