#pragma once
// The MD-only deck (`mpmx md DECK`): potential, lattice, temperature, integration,
// deformation and output, read with every error named (key, value, reason).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/app/region_tracks.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/bar.hpp"
#include "mpmx/md/jet.hpp"
#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/particles/oriented_lattice.hpp"
#include "mpmx/md/rod.hpp"
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

struct MdConfig {
  PotentialSpec potential;
  std::array<int, 3> cells{5, 5, 5};
  double lattice_constant = 3.615;  // Angstrom
  // [lattice]'s crystal (type, constant, c_over_a, orient); cells counts its periodic
  // tiles (particles/oriented_lattice.hpp), the cubic cells of fcc along the axes.
  particles::LatticeSpec lattice;
  double strain_x = 0.0;            // initial engineering strain (section 6.2)
  double temperature = 0.0;         // K, target; atoms start at twice it (section 6.2)
  std::uint64_t seed = 1;
  std::int64_t relax_steps = 0;     // zero-strain-rate relaxation before the run (section 6.2)
  double dt = 0.001;                // ps
  std::int64_t steps = 0;
  std::int64_t thermo = 100;        // steps between thermo rows
  std::int64_t dump_every = 0;      // LAMMPS dump frames (0: none), multiple of thermo
  std::vector<std::string> dump_fields;  // per-atom columns of the dump (dump.hpp)
  std::string ensemble = "nve";     // nve, nvt, npt, nph, nphug (a [bar], [jet] or [rod]: nve)
  NoseHooverOptions nose_hoover;    // the thermostat and barostat of nvt, npt, nph, nphug
  Mat3 velocity_gradient{};         // 1/ps
  bool streaming = false;           // start with the streaming velocity of the gradient
  SystemOptions options;
  // Optional lattice-constant scan (M1): energy per atom at `scan_points` values.
  double scan_from = 0, scan_to = 0;
  int scan_points = 0;
  // Optional 0 K elastic tensor ([elastic], md/elastic_constants.hpp) of the deck's
  // crystal at the potential's minimum ("minimum") or at [lattice].constant ("deck").
  bool elastic = false;
  bool elastic_at_minimum = true;
  double elastic_strain = 1e-5;
  bool elastic_relax = true;
  double elastic_temperature = 0;    // K; above 0: strained NVT boxes, time-averaged stresses
  int elastic_equilibrate_steps = 3000, elastic_sample_steps = 5000;
  // Optional direct-MD bar ([bar]): walls along x, binned stress every `bar_every` steps.
  bool bar = false;
  BarConfig bar_config;
  std::int64_t bar_every = 100;
  // Optional direct-MD copper jet ([jet], sec. 7.1): run.steps and the record interval
  // follow from jet.duration_ps and jet.record_every_ps times the scale.
  bool jet = false;
  JetConfig jet_config;
  std::array<int, 2> jet_bins{400, 50};
  std::int64_t jet_every = 1000;  // steps between records (bins, front)
  // Optional all-atom flyer on a rod ([rod], seed 004 sec. 4.1.1): the target equilibrated
  // for rod_equilibrate_steps with the flyer held, then the flyer sent at rod_velocity
  // along +x for run.steps, the region tracks recorded every tracks.every steps.
  bool rod = false;
  RodConfig rod_config;
  double rod_velocity = 5.0;                // Angstrom/ps
  std::int64_t rod_equilibrate_steps = 0;
  std::int64_t rod_rescale_every = 50;      // velocity rescaling to the temperature (0: none)
  // `mpmx md --still`: the flyer released at rest (the undriven twin of the run: the same
  // random streams, so the two agree until the wave arrives; dpd_study.py subtracts it).
  bool still = false;
  TrackSettings tracks;
  std::string deck_file;
  // [case], optional in an md deck: id (default the deck file's name), title, seed.
  std::string id, title, seed_ref;
};

// Reads and validates; throws InputError listing every problem (Deck::finish()).
MdConfig read_md_config(io::Deck& deck);

}  // namespace mpmx::app::md
