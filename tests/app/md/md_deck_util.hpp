#pragma once
// An MD deck in memory for the deck reader's and the budget's tests: a Lennard-Jones
// lattice of `cells` fcc cells run `steps` steps, read through read_md_config.
#include <string>

#include "mpmx/app/md/config.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::test {

inline std::string lj_deck(const std::string& cells, const std::string& steps) {
  return "[potential]\nstyle = \"lj\"\nepsilon = 0.4\nsigma = 2.3\ncutoff = 5.0\nmass = 63.5\n"
         "[lattice]\nconstant = 3.615\ncells = [" + cells + "]\n[run]\ndt = 0.001\nsteps = " + steps + "\n";
}

inline app::md::MdConfig md_config_of(const std::string& text) {
  auto deck = io::Deck::from_string(text, "budget.toml");
  return app::md::read_md_config(deck);
}

}  // namespace mpmx::test
