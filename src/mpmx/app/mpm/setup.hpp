#pragma once
// Builds the initial state of a run from its configuration: grid, evenly placed
// particles (per_cell per cell and axis, each owning an equal part of its cell; in 2-D
// and 3-D those whose centres lie in the deck's bodies), material, initial fields and
// boundaries.
#include <array>
#include <vector>

#include "mpmx/app/mpm/config.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

// The points a deck places, in the run's order (grouped by law, stably: a one-law deck
// keeps the grid order): each one's place, body (-1: a deck without bodies) and law (an
// index into `laws`, the deck's [material] first).
struct PlacedPoints {
  std::vector<std::array<double, 3>> at;
  std::vector<int> owner, law;
  std::vector<const material::Model*> laws;
};
PlacedPoints placed_points(const MpmConfig& c);

// initialize_material = false leaves per-point material state to a checkpoint;
// `threads` is the MD closure's (0: OpenMP's default).
template <int Dim>
mpm::State<Dim> make_state(const MpmConfig& c, bool initialize_material = true, int threads = 0);
// A 1-D deck's state.
inline mpm::State<1> make_state(const MpmConfig& c, bool initialize_material = true) {
  return make_state<1>(c, initialize_material, 0);
}

}  // namespace mpmx::app
