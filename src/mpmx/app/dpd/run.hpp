#pragma once
// Runs a DPD deck: builds the particles, an optional Berendsen equilibration (rigid
// groups held at rest, every particle DPD), then the run (rigid groups at their
// velocities, a concurrent run's continuum points marked, the mover in place); writes
// DIR/thermo.csv, DIR/dump.lammpstrj (when asked), the analysis tables and DIR/run.json.
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include <toml++/toml.h>

#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/run_control.hpp"
#include "mpmx/dpd/mover.hpp"
#include "mpmx/dpd/system.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

// The particles, groups and velocities of a deck (rigid groups at rest: the run sets
// their velocities after the equilibration).
System build_system(const DpdConfig& config, int threads);

struct DpdRunSummary {
  long particles = 0;
  long steps = 0;
  double wall_seconds = 0;
  double particle_steps_per_second = 0;
  double energy_drift = 0;  // DPDE: least-squares dE/dstep x 1000 / mean K over the run's rows, else 0
  double temperature = 0;   // K, mean kinetic temperature over the run's thermo rows
  // The analysis (NaN where not asked): wave speed (Angstrom/ps), tensile initial slope
  // and peak stress (GPa) and the strain at the peak, CNA's interior fcc fraction at the
  // run's start and end.
  double wave_speed = std::nan(""), initial_slope = std::nan(""), peak_stress = std::nan(""), peak_strain = std::nan("");
  double fcc_start = std::nan(""), fcc_end = std::nan("");
  bool interrupted = false;  // stopped on Ctrl-C, SIGTERM or stop_after: a checkpoint written
  std::int64_t step = 0, last_step = 0;  // the system's step where it ended, and the deck's last
};

// Ctrl-C or SIGTERM stops it at the next record with a checkpoint, from which
// `options.resume` continues bit-for-bit (app/run_control.hpp).
DpdRunSummary run_dpd(const DpdConfig& config, const std::string& out_dir, const toml::table& deck_echo,
                      int threads = 1, const RunControlOptions& options = {}, const MoverFactory& mover = {});

}  // namespace mpmx::app::dpd
