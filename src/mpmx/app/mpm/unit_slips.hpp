#pragma once
// `check`'s warnings of a unit slip in a continuum deck that names its unit system: a
// velocity, density or elastic modulus far outside what any solid has in those units
// (a 1000 km/s flyer in nm_ps_GPa: m/s typed for km/s). Warnings, not refusals: the
// deck may mean it.
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// One sentence per suspect value, naming the key, its value in SI and the likely slip;
// none for a deck in units of its own ("dimensionless ...").
std::vector<std::string> unit_slips(const MpmConfig& c);

}  // namespace mpmx::app
