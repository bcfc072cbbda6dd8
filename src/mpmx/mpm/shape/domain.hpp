#pragma once
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm::shape {
// GIMP (eqs. 3.17-3.20) when `integrate` is true: S_ip is the average of the hat over
// the particle domain; CPDI (eqs. 3.23-3.24) when false: the average of its two corner
// values. Both have the gradient (S_i(x_2) - S_i(x_1)) / l_p.
void evaluate_domain(const Grid<1>& g, const Particles<1>& p, Stencil<1>& st, bool integrate);
}
