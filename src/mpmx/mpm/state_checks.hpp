#pragma once
// What the run loop asks of the state after a step: every value finite, every volume
// positive, and (dt = "cfl") the stable step.
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// A NaN or Inf anywhere stops the run naming the step, the particle and the field.
template <int Dim>
void check_finite(const State<Dim>& s);

// cfl x the smallest cell side / max over points of (sound speed + speed), a piston's or
// a velocity face's speed over the step among the speeds (mpm/boundary_speed.hpp).
template <int Dim>
double stable_dt(const State<Dim>& s, double cfl);

// A particle whose volume is no longer positive has failed.
template <int Dim>
void check_volumes(const State<Dim>& s);

}  // namespace mpmx::mpm
