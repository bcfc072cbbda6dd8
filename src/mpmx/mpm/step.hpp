#pragma once
// One explicit continuum step, dissertation sec. 3.1 steps 3-10.
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// The step as written (stencil, p2g, solve, g2p, material), for every scheme and
// dimension: the production path in 2-D and 3-D and the reference in 1-D.
template <int Dim>
void step_stencil(State<Dim>& s, double dt);

// The production step: in 1-D through the fused kernels where the scheme has them
// (mpm, ddmp, ddmp_subpoints), else step_stencil.
template <int Dim>
void step(State<Dim>& s, double dt);

}  // namespace mpmx::mpm
