#pragma once
// What an md deck's numbers say that no range check can: an element put on another
// lattice than its potential file names, or a box built far from zero stress (a lattice
// constant that is not the potential's for that crystal, such as Cu's atoms on Ta's bcc
// lattice, which starts at -3.7 GPa and runs). `mpmx md --check` prints them and the run
// says them on the terminal before it starts.
#include <string>
#include <vector>

#include "mpmx/app/md/config.hpp"

namespace mpmx::app::md {

std::vector<std::string> md_deck_warnings(const MdConfig& c, const Potential& pot);

}  // namespace mpmx::app::md
