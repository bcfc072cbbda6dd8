#pragma once
// Reads and checks a continuum deck. Every problem is reported at once, each naming
// the key, the value and the reason; nothing runs on a deck with an error.
#include <string>

#include "mpmx/mpm/config.hpp"

namespace mpmx::io {

// Throws InputError listing every error of the deck.
mpm::MpmConfig read_mpm_deck(const std::string& path);
mpm::MpmConfig read_mpm_deck_text(const std::string& text, const std::string& name = "deck");

}  // namespace mpmx::io
