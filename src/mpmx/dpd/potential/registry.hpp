#pragma once
// The DPD conservative pair potential U(r) (seed 004 eq. 2.3), chosen by name in the
// deck's [potential] table. Adding one: its own header (a struct with `name`, `cutoff`,
// `eval`, `describe`, `read`) and one entry in PairPotentials below; the force kernels
// are instantiated per alternative and dispatched once per force evaluation.
#include <string>
#include <variant>
#include <vector>

#include "mpmx/core/registry.hpp"
#include "mpmx/core/table.hpp"
#include "mpmx/dpd/potential/morse.hpp"
#include "mpmx/dpd/potential/nm.hpp"
#include "mpmx/dpd/potential/soft.hpp"

namespace mpmx::dpd {

using PairPotentials = Registry<SoftPotential, MorsePotential, NmPotential>;

// One pair potential: an entry with its parameters.
using PairPotential = VariantOf<PairPotentials>;

std::vector<std::string> pair_potential_names();
// Reads `style` and that style's parameters; errors are recorded in the table. (A deck's
// `file = ...` instead, a potential file as `mpmx fit-dpd` writes, is read by the deck's
// reader, app/dpd/config.hpp.)
PairPotential read_pair_potential(Table& s);
inline PairPotential read_pair_potential(Table&& s) { return read_pair_potential(s); }
double cutoff(const PairPotential& p);
std::string describe(const PairPotential& p);
std::string style_name(const PairPotential& p);

}  // namespace mpmx::dpd
