#pragma once
// One explicit continuum step, dissertation sec. 3.1 steps 3-10.
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

void step(State<1>& s, double dt);

}  // namespace mpmx::mpm
