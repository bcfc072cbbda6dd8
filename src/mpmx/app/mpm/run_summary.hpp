#pragma once
// What run.json says of a finished (or stopped, or interrupted) continuum run: status,
// conservation, errors, the MD boxes' work, the step's phases.
#include <array>
#include <string>

#include "mpmx/app/mpm/config.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/io/run_record.hpp"

namespace mpmx::app {

// The Euclidean norm of a tally kept as three components (momentum, impulse).
double norm(const std::array<double, 3>& v);

// `failure`: the RunError that stopped the run ("" when none); `checkpoint`: where an
// interrupted run's checkpoint lies.
template <int Dim>
void record_run(const MpmConfig& c, const RunResultOf<Dim>& r, const std::string& failure,
                const std::string& checkpoint, io::RunRecord& rec);

}  // namespace mpmx::app
