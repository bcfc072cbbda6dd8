#include "mpmx/app/deck_kind.hpp"

#include <map>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app {

namespace {

std::map<DeckKind, DeckCheck>& checks() {
  static std::map<DeckKind, DeckCheck> registry;
  return registry;
}

}  // namespace

DeckKind deck_kind(const std::string& path) {
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const std::exception&) {
    return DeckKind::continuum;  // its reader says where the TOML is wrong
  }
  auto has = [&](const char* key) { return t.contains(key); };
  if (has("grid") && !has("dpd") && !has("block")) return DeckKind::continuum;
  if (has("densities")) return DeckKind::fit_dpd;
  if (has("dpd") || has("block") || has("equilibrate")) return DeckKind::dpd;
  if (has("lattice") || has("bar") || has("jet") || (has("potential") && has("run"))) return DeckKind::md;
  if (has("potential") && t.size() == 1) return DeckKind::potential;
  return DeckKind::continuum;
}

const char* deck_kind_name(DeckKind kind) {
  switch (kind) {
    case DeckKind::continuum: return "continuum";
    case DeckKind::md: return "md";
    case DeckKind::dpd: return "dpd";
    case DeckKind::fit_dpd: return "fit-dpd";
    case DeckKind::potential: return "potential";
  }
  return "continuum";
}

void register_deck_check(DeckKind kind, DeckCheck check) { checks()[kind] = std::move(check); }

bool check_deck_of_another_kind(const std::string& deck, bool force) {
  const DeckKind kind = deck_kind(deck);
  if (kind == DeckKind::continuum) return false;
  if (kind == DeckKind::potential)
    throw InputError(fmt::format("{}: a DPD potential file (what `mpmx fit-dpd` writes, a [potential] table "
                                 "alone), not a deck: a DPD deck names it as [potential] file",
                                 deck));
  const auto it = checks().find(kind);
  if (it == checks().end())
    throw std::logic_error(fmt::format("no check registered for {} decks", deck_kind_name(kind)));
  it->second(deck, force);
  return true;
}

}  // namespace mpmx::app
