#pragma once
// Reads and checks a continuum deck. Every problem is reported at once, each naming
// the key, the value and the reason; nothing runs on a deck with an error.
#include <string>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// Throws InputError listing every error of the deck.
MpmConfig read_mpm_deck(const std::string& path);
MpmConfig read_mpm_deck_text(const std::string& text, const std::string& name = "deck");

}  // namespace mpmx::app
