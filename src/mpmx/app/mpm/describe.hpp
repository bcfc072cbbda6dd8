#pragma once
// What `mpmx check` says of a continuum deck's drives and records beyond its size: each
// piston (its speed, how far it moves), each velocity face that pushes into the material
// (a note: a drive is a piston) and each gauge (what it follows, its table).
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// One line per piston, per pushing velocity face and per gauge, in the deck's order.
std::vector<std::string> describe_pistons_and_gauges(const MpmConfig& c);

}  // namespace mpmx::app
