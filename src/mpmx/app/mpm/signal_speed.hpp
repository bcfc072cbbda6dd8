#pragma once
// The fastest signal of a deck's initial state, c + v: the largest wave speed of its laws
// (a gas's over the initial pressure profile) plus the fastest speed a point has or the
// boundary gives it (a body's velocity plus its spin times its radius; a piston's, any
// speed of its table; a velocity face's). The deck's CFL limit (a number dt) and the first
// step of dt = "cfl" are taken from it, as the run's steps are (mpm::stable_dt).
#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// The smallest cell side.
double smallest_cell(const MpmConfig& c);

// c + v above; 0 when the deck's law or grid is not known (its reading said why).
double initial_signal_speed(const MpmConfig& c);

// v above: the fastest speed a body's point has or the boundary gives.
double fastest_drive(const MpmConfig& c);

// The step every continuum step must be a whole number of (md_closure's MD step in
// continuum units), 0 where any step does; and dt cut down to whole ones (at least one).
double time_quantum(const MpmConfig& c);
double whole_quanta(double dt, double quantum);

// The deck's dt = "cfl": cfl x smallest_cell / initial_signal_speed in whole quanta, the
// first step's (later ones follow the state).
double first_cfl_step(const MpmConfig& c);

}  // namespace mpmx::app
