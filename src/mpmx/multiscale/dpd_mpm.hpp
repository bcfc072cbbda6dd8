#pragma once
// The mover of a DPD deck with [grid] (and [continuum]): the DPD/MPM grid over the
// particles' extent at the run's start plus the margin, and, for a concurrent run, the
// continuum points' cubic elastic law with the DPD model's constants (dpd/elastic.hpp).
#include "mpmx/dpd/run.hpp"

namespace mpmx::multiscale {

// Empty for a DPD-only deck.
dpd::MoverFactory dpd_mpm_mover(const dpd::DpdConfig& config, int threads);

}  // namespace mpmx::multiscale
