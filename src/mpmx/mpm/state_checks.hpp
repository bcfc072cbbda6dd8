#pragma once
// What the run loop asks of the state after a step: every value finite, every volume
// positive (the stable step is mpm/step_limit.hpp's).
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// A NaN or Inf anywhere stops the run naming the step, the particle and the field.
template <int Dim>
void check_finite(const State<Dim>& s);

// A particle whose volume is no longer positive has failed.
template <int Dim>
void check_volumes(const State<Dim>& s);

}  // namespace mpmx::mpm
