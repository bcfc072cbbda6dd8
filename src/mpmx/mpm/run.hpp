#pragma once
// A whole continuum run: set-up, the step loop, records, comparison with the
// reference, conservation figures, run.json and figures.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mpmx/mpm/config.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

struct RunOptions {
  std::string out_dir;   // "" = write nothing (tests)
  bool quiet = false;    // no progress line
  bool plot = true;      // call tools/plot when the deck allows and matplotlib is present
};

struct FieldError {
  double l1 = 0.0, l2 = 0.0;  // max over the compared times
  double peak = 0.0;          // max |u - r| / max |r - b|: overshoot and spikes
};

struct RunResult {
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  std::map<std::string, FieldError> errors;   // by field; also "energy", "front_speed"
  double front_speed = 0.0;                   // shock_front cases
  // Conservation (S4).
  double mass_particles = 0.0, mass_nodes = 0.0;
  double momentum_initial = 0.0, momentum_final = 0.0, boundary_impulse = 0.0;
  double momentum_scale = 0.0;                // max sum m|v| seen at the ends
  double max_force_sum = 0.0;                 // max_steps |sum f| / sum |f|
  double kinetic_initial = 0.0, kinetic_final = 0.0, stress_work = 0.0, boundary_work = 0.0;
  double max_kinetic = 0.0;
  State<1> state;                             // the final state
  double energy_error() const { return std::abs(kinetic_final - kinetic_initial + stress_work - boundary_work); }
  double momentum_error() const { return std::abs(momentum_final - momentum_initial - boundary_impulse); }
};

RunResult run_mpm(const MpmConfig& c, const RunOptions& o);

}  // namespace mpmx::mpm
