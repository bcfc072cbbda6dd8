#pragma once
// Runs a DPD deck: builds the particles, an optional Berendsen equilibration (rigid
// groups held at rest), then the run (rigid groups at their velocities); writes
// DIR/thermo.csv, DIR/dump.lammpstrj (when asked) and DIR/run.json.
#include <string>

#include <toml++/toml.h>

#include "mpmx/dpd/config.hpp"
#include "mpmx/dpd/system.hpp"

namespace mpmx::dpd {

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
};

DpdRunSummary run_dpd(const DpdConfig& config, const std::string& out_dir, const toml::table& deck_echo,
                      int threads = 1, bool quiet = false);

}  // namespace mpmx::dpd
