#pragma once
// The work a run does before its points are built that reading the deck leaves to it
// (md_closure's NPT box, prepare = "npt": material::Model::prepared). `check` states it;
// the run does it first, so that a deck's checks never wait on it.
#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// The deck with its laws after that work: the points' density the prepared crystal's,
// and with dt = "cfl" the first step's dt taken from it, as the deck's reading would have
// (the run's records the same as when the reading did the work). `c` itself when no law
// has any.
MpmConfig prepared_for_run(const MpmConfig& c);

}  // namespace mpmx::app
