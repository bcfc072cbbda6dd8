#pragma once
// The MD potentials a deck's [potential] table names by `style`. Each is an entry in its
// own files (its parameters, their reader, the force kernel it makes, the LAMMPS pair
// lines for it: eam.hpp, lj.hpp, sutton_chen.hpp), registered by the one line below.
#include <string>

#include "mpmx/core/registry.hpp"
#include "mpmx/core/table.hpp"
#include "mpmx/md/potential/eam.hpp"
#include "mpmx/md/potential/lj.hpp"
#include "mpmx/md/potential/sutton_chen.hpp"

namespace mpmx::md {

using Potentials = Registry<EamSpec, LjSpec, SuttonChenSpec>;

// One potential's parameters: its entry's spec.
using PotentialSpec = VariantOf<Potentials>;

// A [potential] table: `style` (eam unless given), then that entry's keys; every problem
// is recorded in the table (the deck's reader reports them all at once).
PotentialSpec read_potential(Table& t, const std::string& deck_dir);
inline PotentialSpec read_potential(Table&& t, const std::string& deck_dir) { return read_potential(t, deck_dir); }

// False when its reader recorded why no potential can be made from the spec (an eam
// file that was not found).
bool complete(const PotentialSpec& spec);

}  // namespace mpmx::md
