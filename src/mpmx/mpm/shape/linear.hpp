#pragma once
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {
void evaluate_linear(const Grid<1>& g, const Particles<1>& p, Stencil<1>& st);
}
