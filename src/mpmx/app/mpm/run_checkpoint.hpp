#pragma once
// A continuum run's checkpoint: the deck's text, the state (mpm state and the laws'
// per-point state, app/mpm/checkpoint.hpp), then what the run loop carries on with (its
// running figures, the errors so far, the record, the tables' lengths), written
// atomically by rank 0 and read by every rank. A run resumed from it continues
// bit-for-bit.
#include <array>
#include <string>

#include "mpmx/app/mpm/comparison.hpp"
#include "mpmx/app/mpm/config.hpp"
#include "mpmx/app/mpm/output.hpp"
#include "mpmx/app/mpm/step_log.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

// The run loop's own figures that a checkpoint carries after the state.
struct RunCarry {
  std::array<double, 3> momentum_initial{};
  double kinetic_initial = 0.0, mass_particles = 0.0, momentum_scale = 0.0, max_kinetic = 0.0;
  double stored_initial = 0.0;
  double wall_before = 0.0;  // wall time of the earlier processes of a resumed run
  StepLog steps;             // dt = "cfl": the steps taken so far
};

template <int Dim>
void save_run_checkpoint(const std::string& path, const MpmConfig& c, const mpm::State<Dim>& s,
                         const RunCarry& carry, const ErrorBook& book, const io::RunRecord& rec,
                         const Output::Marks& marks);

// Fills s (made by make_state(c, false)), carry, book, rec and the tables' lengths;
// throws InputError naming the file and byte of anything that does not fit the deck.
template <int Dim>
Output::Marks load_run_checkpoint(const std::string& path, const MpmConfig& c, mpm::State<Dim>& s, RunCarry& carry,
                                  ErrorBook& book, io::RunRecord& rec);

}  // namespace mpmx::app
