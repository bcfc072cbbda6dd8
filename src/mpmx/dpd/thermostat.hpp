#pragma once
// Berendsen thermostat (Berendsen et al. 1984), for equilibration (seed 004 sec. 4.1.1:
// 1000 ps at 298 K before impact): after a step the mobile particles' velocities are
// scaled about their mean by lambda = sqrt(1 + dt/tau (T0/T - 1)), T the kinetic
// temperature (3N-3 degrees of freedom). In DPDE the internal temperatures relax
// likewise, u_i <- u_i + dt/tau (C_v T0 - u_i), so the equilibrated state has
// internal and kinetic temperatures at T0.
#include "mpmx/dpd/particles.hpp"

namespace mpmx::dpd {

struct Berendsen {
  double temperature = 0;  // K
  double tau = 1;          // ps
};

// Kinetic temperature of the mobile particles about their mean velocity (K).
double kinetic_temperature(const Particles& p);

// One thermostat application after a step of dt; heat_capacity (eV/K) > 0 also relaxes u.
void berendsen_rescale(Particles& p, const Berendsen& b, double dt, double heat_capacity);

}  // namespace mpmx::dpd
