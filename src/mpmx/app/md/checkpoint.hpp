#pragma once
// An `mpmx md` run's checkpoint (app/run_control.hpp; kind md_run, counted in atoms): the
// system (md::System::save: atoms, box, walls, step, random stream, the neighbour list's
// build state) and the figures the run tracks record by record (the jet's fronts). A run
// stops only where the uninterrupted run ends an advance (a record or thermo row): an
// advance's half kicks at its ends differ in the last bit from the whole kicks inside
// one, so a resumed run is bit-for-bit only from there.
#include <cstdint>
#include <functional>
#include <vector>

#include "mpmx/app/run_control.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::app::md {

// The figures a run tracks record by record, as lists of numbers.
using Tracked = std::vector<std::vector<double>>;

// On --resume: `sys` (built from the deck: its potential, options, atoms and frozen
// piston) becomes the checkpoint's state, the tables are cut back; returns what the run
// tracked. The checkpoint's step must lie below `last_step`, the deck's last.
Tracked resume_md(RunControl& control, mpmx::md::System& sys, std::int64_t last_step);

// At a record before the last: true when the run is to stop here, its checkpoint written.
bool stop_md_at(RunControl& control, const mpmx::md::System& sys, const Tracked& tracked);

// The same with the run's own fields after the system (written and read in one order).
void resume_md_with(RunControl& control, mpmx::md::System& sys, std::int64_t last_step,
                    const std::function<void(CheckpointIn&)>& read_rest);
bool stop_md_with(RunControl& control, const mpmx::md::System& sys,
                  const std::function<void(CheckpointOut&)>& write_rest);

}  // namespace mpmx::app::md
