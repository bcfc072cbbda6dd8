#pragma once
// What a DPD deck will cost before it runs, in work: particles x (equilibration + run)
// steps. A deck that would run for more than about a day is refused unless forced
// (`dpd --force`), with the key and the figure; `dpd --check` prints the estimate. (The
// memory is refused at read: app/dpd/config.cpp.)
#include <string>

#include "mpmx/app/dpd/config.hpp"

namespace mpmx::app::dpd {

// Particle-steps a second on one core at the seed's density and 12 Angstrom cutoff
// (D1: 12,800 particles, 6,000 steps in about 2 minutes): the typical figure, for decks
// of under a minute by it; a longer one is estimated at the rate its own system is timed
// at here (particle_rate.hpp).
inline constexpr double kDpdParticleStepsPerSecond = 5e5;
inline constexpr double kDpdTimeRateAboveSeconds = 60.0;
inline constexpr double kDpdWorkLimitSeconds = 86400.0;

struct DpdBudget {
  double particles = 0;       // in the blocks
  double particle_steps = 0;  // particles x (equilibrate.steps + run.steps)
  std::string work_key;       // "run.steps" or "equilibrate.steps + run.steps"
  double rate = kDpdParticleStepsPerSecond;  // particle-steps a second of one core
  bool rate_measured = false;                // that rate timed here for this deck
  double seconds() const { return particle_steps / rate; }
};

double block_particles(const DpdConfig& c);
// Pairs within cutoff + skin, from the counts: each block's particles at its own density
// (fcc 4 / a^3, a random fill its count over its volume), as the neighbour list will hold.
double block_pairs(const DpdConfig& c);
DpdBudget estimate_dpd(const DpdConfig& c);
// Throws InputError when the work exceeds a day, unless `force`.
void check_dpd_work(const DpdBudget& b, bool force);

}  // namespace mpmx::app::dpd
