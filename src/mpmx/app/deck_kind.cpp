#include "mpmx/app/deck_kind.hpp"

#include <map>
#include <optional>

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

namespace {

// The kind the deck's tables show, or none: a file TOML cannot read (or no file), or
// tables of no kind (a continuum deck without [grid]); the reader of the command it was
// given to then says what is wrong.
std::optional<DeckKind> evident_kind(const std::string& path) {
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  auto has = [&](const char* key) { return t.contains(key); };
  if (has("grid") && !has("dpd") && !has("block")) return DeckKind::continuum;
  if (has("densities")) return DeckKind::fit_dpd;
  if (has("dpd") || has("block") || has("equilibrate")) return DeckKind::dpd;
  if (has("lattice") || has("bar") || has("jet") || (has("potential") && has("run"))) return DeckKind::md;
  if (has("potential") && t.size() == 1) return DeckKind::potential;
  return std::nullopt;
}

}  // namespace

DeckKind deck_kind(const std::string& path) { return evident_kind(path).value_or(DeckKind::continuum); }

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

const char* deck_command(DeckKind kind) {
  switch (kind) {
    case DeckKind::continuum: return "run";
    case DeckKind::md: return "md";
    case DeckKind::dpd: return "dpd";
    case DeckKind::fit_dpd: return "fit-dpd";
    case DeckKind::potential: return "";
  }
  return "run";
}

namespace {

// What makes a deck of `kind` one, for the sentence that names its command.
const char* kind_mark(DeckKind kind) {
  switch (kind) {
    case DeckKind::continuum: return "a [grid] table";
    case DeckKind::md: return "a [lattice], [bar], [jet] or [potential] and [run] table";
    case DeckKind::dpd: return "a [dpd], [[block]] or [equilibrate] table";
    case DeckKind::fit_dpd: return "a [densities] table";
    case DeckKind::potential: return "a [potential] table alone";
  }
  return "";
}

void refuse_potential_file(const std::string& deck) {
  throw InputError(fmt::format("{}: a DPD potential file (what `mpmx fit-dpd` writes, a [potential] table "
                               "alone), not a deck: a DPD deck names it as [potential] file",
                               deck));
}

}  // namespace

void require_deck_kind(const std::string& deck, DeckKind kind) {
  const std::optional<DeckKind> evident = evident_kind(deck);
  if (!evident || *evident == kind) return;  // the command's reader names what is wrong
  const DeckKind is = *evident;
  if (is == DeckKind::potential) refuse_potential_file(deck);
  throw InputError(fmt::format("{} is {} {} deck ({}): run it with `mpmx {} {}`, not `mpmx {}`", deck,
                               is == DeckKind::md ? "an" : "a", deck_kind_name(is), kind_mark(is), deck_command(is),
                               deck, deck_command(kind)));
}

void register_deck_check(DeckKind kind, DeckCheck check) { checks()[kind] = std::move(check); }

bool check_deck_of_another_kind(const std::string& deck, bool force) {
  const DeckKind kind = deck_kind(deck);
  if (kind == DeckKind::continuum) return false;
  if (kind == DeckKind::potential) refuse_potential_file(deck);
  const auto it = checks().find(kind);
  if (it == checks().end())
    throw std::logic_error(fmt::format("no check registered for {} decks", deck_kind_name(kind)));
  it->second(deck, force);
  fmt::print("  {} deck: run it with `mpmx {} {}`\n", deck_kind_name(kind), deck_command(kind), deck);
  return true;
}

}  // namespace mpmx::app
