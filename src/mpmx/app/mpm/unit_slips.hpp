#pragma once
// `check`'s warnings of a unit slip in a continuum deck that names its unit system: a
// velocity, density or elastic modulus far outside what any solid has in those units
// (a 1000 km/s flyer in nm_ps_GPa: m/s typed for km/s). Warnings, not refusals: the
// deck may mean it. Every velocity a deck holds is judged: the bodies' (and their spin's
// rim speed), [initial.velocity], the pistons' and the velocity faces'; every law's
// density (a gas's too: none is denser than a solid), a solid's modulus (the uniaxial one
// it names, else density x wave speed^2) and a gas's sound speed.
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// One sentence per suspect value, naming the key, its value in SI and the likely slip;
// none for a deck in units of its own ("dimensionless ...").
std::vector<std::string> unit_slips(const MpmConfig& c);

// The velocities' sentences alone: the hint a CFL error carries (a speed typed in m/s for
// km/s is what usually makes a numeric dt too long).
std::vector<std::string> velocity_slips(const MpmConfig& c);

// How messages name body b: as run.json and the points' `body` field number it (from 0),
// with its name (control characters escaped): `[[body]] 0 ("flyer")`.
std::string body_label(const MpmConfig& c, std::size_t b);

}  // namespace mpmx::app
