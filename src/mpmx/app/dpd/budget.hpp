#pragma once
// What a DPD deck will cost before it runs, in work: particles x (equilibration + run)
// steps. A deck that would run for more than about a day is refused unless forced
// (`dpd --force`), with the key and the figure; `dpd --check` prints the estimate. (The
// memory is refused at read: app/dpd/config.cpp.)
#include <string>

#include "mpmx/app/dpd/config.hpp"

namespace mpmx::app::dpd {

// Particle-steps a second on one core at the seed's density and 12 Angstrom cutoff
// (D1: 12,800 particles, 6,000 steps in about 2 minutes), for the estimate only.
inline constexpr double kDpdParticleStepsPerSecond = 5e5;
inline constexpr double kDpdWorkLimit = 86400.0 * kDpdParticleStepsPerSecond;

struct DpdBudget {
  double particles = 0;       // in the blocks
  double particle_steps = 0;  // particles x (equilibrate.steps + run.steps)
  std::string work_key;       // "run.steps" or "equilibrate.steps + run.steps"
  double seconds() const { return particle_steps / kDpdParticleStepsPerSecond; }
};

double block_particles(const DpdConfig& c);
DpdBudget estimate_dpd(const DpdConfig& c);
// Throws InputError when the work exceeds kDpdWorkLimit, unless `force`.
void check_dpd_work(const DpdBudget& b, bool force);

}  // namespace mpmx::app::dpd
