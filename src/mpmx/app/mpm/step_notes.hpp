#pragma once
// What `mpmx check` says of a continuum deck's time step: the step it starts with and
// what sets it, and the step the state a planar shock at the deck's fastest body or
// piston reaches allows (each law's Hugoniot: md_closure's from its crystal's uniaxial
// curve and the Rayleigh line, Mie-Gruneisen's from Us = c0 + s up), with a warning where
// a fixed dt exceeds it.
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// Lines to print as they are; a warning's starts with "warning: ".
std::vector<std::string> describe_time_step(const MpmConfig& c);

}  // namespace mpmx::app
