#pragma once
// DPD's particle-steps a second on one core, timed on this machine for the deck at hand
// (the cost per particle follows the deck's density, cutoff, integrator and groups).
#include "mpmx/app/dpd/config.hpp"

namespace mpmx::app::dpd {

// The deck's system built and stepped on one thread for about a tenth of a second (its
// first step, which builds the neighbour lists, not timed). 0 when it is not timed: a
// system whose building and first step alone would take long (over 2e5 particles or 1e6
// pairs within reach), or one that does not build.
double measure_particle_steps_per_second(const DpdConfig& c);

}  // namespace mpmx::app::dpd
