#pragma once
// One front door: `mpmx check DECK` checks every kind of deck, each by its own command's
// check (`run`'s for a continuum deck, `md --check`, `dpd --check`, `fit-dpd --check`).
// The kind is read from the deck's tables; each command registers its check here.
#include <functional>
#include <string>

namespace mpmx::app {

enum class DeckKind { continuum, md, dpd, fit_dpd, potential };

// The kind of the deck at `path` by its top-level tables: [densities] a fit-dpd deck;
// [dpd], [[block]] or [equilibrate] a DPD deck; [lattice], [bar] or [jet] (or [potential]
// and [run] without [grid]) an MD deck; [potential] alone a DPD potential file (what
// fit-dpd writes, not a deck); anything else, a file TOML cannot read included, a
// continuum deck (whose reader names what is wrong).
DeckKind deck_kind(const std::string& path);
const char* deck_kind_name(DeckKind kind);
// The command that runs a deck of `kind` ("run", "md", "dpd", "fit-dpd"; "" for a potential file).
const char* deck_command(DeckKind kind);

// Every running command's first step: a deck whose tables show another kind is refused
// with one sentence naming the command that runs it (InputError, exit 2), before its
// reader would list the keys it does not know. A file TOML cannot read, or one of no
// evident kind, is left to the command's reader, which names what is wrong.
void require_deck_kind(const std::string& deck, DeckKind kind);

// A command's check of a deck: prints its estimate, throws InputError on what its run
// would refuse. `force`: a work estimate over a day is said, not refused.
using DeckCheck = std::function<void(const std::string& deck, bool force)>;
void register_deck_check(DeckKind kind, DeckCheck check);

// `check`'s dispatch: true when the deck is of another kind than continuum and that
// kind's check ran (and then said which command runs it); a potential file is refused
// with a sentence saying what it is.
bool check_deck_of_another_kind(const std::string& deck, bool force);

}  // namespace mpmx::app
