#pragma once
// A shocked state on the Hugoniot from the jump conditions (Rankine-Hugoniot): with the
// unshocked volume V0 and stress P0 of a mass M and the shocked V and P along the shock,
// P - P0 = rho0 Us up and V / V0 = 1 - up / Us.
#include "mpmx/md/system.hpp"

namespace mpmx::md {

struct HugoniotPoint {
  double rho0 = 0;        // g/cm^3
  double us = 0, up = 0;  // km/s; 0 where the state is not compressed
};

// The box's atoms' mass; volumes in A^3, stresses (compression positive) in GPa.
HugoniotPoint jump_conditions(const System& s, double v0, double p0, double v, double p);

}  // namespace mpmx::md
