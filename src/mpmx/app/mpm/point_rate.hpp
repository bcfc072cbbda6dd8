#pragma once
// The continuum's point-steps a second on one core, timed on this machine for the deck at
// hand, so that `check` and `run` estimate its work at the rate this build runs it (the
// 1-D fused kernels and the 2-D and 3-D stencils differ by two orders of magnitude, and
// schemes and laws by several times within each).
#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// The deck's grid coarsened to a few thousand points (its bodies, scheme, law, boundaries
// and dt kept), stepped on one thread for about a tenth of a second. 0 when it is not
// timed: a law with a model inside its points (md_closure times its boxes itself), or a
// coarse state that does not build or step.
// `points`, `subpoints`, `nodes`: the deck's, as its estimate counted them.
double measure_point_steps_per_second(const MpmConfig& c, double points, double subpoints, double nodes);

}  // namespace mpmx::app
