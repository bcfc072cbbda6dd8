#pragma once
// [case] of every deck kind (continuum, md, dpd, fit-dpd): its id, title, seed and
// units, under one rule for the units (core/units.hpp's case_units_problem).
#include <string>
#include <string_view>

#include "mpmx/io/deck.hpp"

namespace mpmx::app {

struct CaseTable {
  std::string id, title, seed, units;
};

// `required`: the deck must have [case] with an id (continuum, dpd and fit-dpd decks);
// otherwise (md decks, which had none) [case] may be left out and the id is the deck
// file's name. `fixed_units`: the one unit system a deck kind's numbers are in (md, dpd
// and fit-dpd: "metal"), which case.units, when given, must name; empty for a continuum
// deck, which names its own (a known system, or "dimensionless ...").
CaseTable read_case_table(io::Section& root, const std::string& deck_name, bool required,
                          std::string_view fixed_units);

}  // namespace mpmx::app
