#pragma once
// Checkpoints of a continuum run: the whole state (particles, tallies, time, the
// material's per-point state such as every MD box) plus whatever the run loop needs to
// carry on, in one binary file written atomically. A run resumed from it continues
// bit-for-bit (tests/app/mpm/interrupt_test.cpp, tests/app/mpm/mpm_run_nd_test.cpp).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "mpmx/app/checkpoint_fields.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

// The framing of a continuum run's checkpoint file (io/checked_file.hpp): the deck's
// canonical text and its point count identify the run it resumes.
io::CheckedKind run_checkpoint_kind(const std::string& deck_text, std::size_t points);

template <int Dim>
void save_state(CheckpointOut& out, const mpm::State<Dim>& s);
// `s` made by make_state(config, false): same grid, scheme and material, no per-point
// material state yet. Throws InputError when the checkpoint does not fit it.
template <int Dim>
void load_state(CheckpointIn& in, mpm::State<Dim>& s);

}  // namespace mpmx::app
