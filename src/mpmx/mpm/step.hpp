#pragma once
// One explicit continuum step, dissertation sec. 3.1 steps 3-10.
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// The step, through the fused 1-D kernels where the scheme has them (mpm, ddmp,
// ddmp_subpoints).
void step(State<1>& s, double dt);

// The same step through the stored stencil, for every scheme: the algorithm as written,
// against which the fused kernels are tested.
void step_stencil(State<1>& s, double dt);

}  // namespace mpmx::mpm
