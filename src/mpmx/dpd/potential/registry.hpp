#pragma once
// The DPD conservative pair potential U(r) (seed 004 eq. 2.3), chosen by name in the
// deck's [potential] table. Adding one: its own header (a struct with `name`, `cutoff`,
// `eval`, `describe`, `read`) and one entry in PairPotential; the force kernels are
// instantiated per alternative and dispatched once per force evaluation.
#include <string>
#include <variant>
#include <vector>

#include "mpmx/dpd/potential/morse.hpp"
#include "mpmx/dpd/potential/nm.hpp"
#include "mpmx/dpd/potential/soft.hpp"
#include "mpmx/io/deck.hpp"

namespace mpmx::dpd {

using PairPotential = std::variant<SoftPotential, MorsePotential, NmPotential>;

std::vector<std::string> pair_potential_names();
// Reads `style` and that style's parameters, or `file`: a potential file (a TOML
// [potential] table, as `mpmx fit-dpd` writes) found as given or in `deck_dir`; errors
// are recorded in the deck.
PairPotential read_pair_potential(io::Section s, const std::string& deck_dir = "");
double cutoff(const PairPotential& p);
std::string describe(const PairPotential& p);
std::string style_name(const PairPotential& p);

}  // namespace mpmx::dpd
