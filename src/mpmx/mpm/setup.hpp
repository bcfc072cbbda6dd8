#pragma once
// Builds the initial state of a run from its configuration: grid, evenly placed
// particles (per_cell per cell, each owning an equal slice of its cell), material,
// initial fields and boundaries.
#include "mpmx/mpm/config.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// initialize_material = false leaves per-point material state to a checkpoint.
State<1> make_state(const MpmConfig& c, bool initialize_material = true);
std::unique_ptr<material::Material<1>> make_material(const MaterialConfig& m);

}  // namespace mpmx::mpm
