#pragma once
// What `mpmx check` says of a continuum deck's drives and records beyond its size: each
// piston (its speed, how far it moves) and each gauge (what it follows, its table).
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// One line per piston and per gauge, in the deck's order.
std::vector<std::string> describe_pistons_and_gauges(const MpmConfig& c);

}  // namespace mpmx::app
