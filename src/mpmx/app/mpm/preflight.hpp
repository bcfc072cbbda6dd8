#pragma once
// Every check a continuum run makes before its work, in one place: `mpmx check` and
// `mpmx run` both call it (after the deck reader's own checks), so what one passes the
// other does not refuse.
#include <cstdint>
#include <string>

#include "mpmx/app/mpm/budget.hpp"
#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

struct MpmPreflight {
  MpmBudget budget;
  // An input not there yet that the run needs: a direct-MD reference whose run has not
  // been made. `check` names it (a study checks its decks before it runs the direct MD
  // they compare with); `run` refuses it.
  std::string pending;
};

// The bodies' placement (bodies.hpp), the memory (always, against `memory_bytes`; 0:
// unknown) and, unless `force`, the work estimate (budget.hpp), and the reference read as
// the run reads it where it is there. Throws InputError naming the key on the first that
// fails.
MpmPreflight preflight_mpm(const MpmConfig& c, int ranks, std::uint64_t memory_bytes, bool force);

// preflight_mpm for a run: a pending input is refused too.
MpmPreflight preflight_mpm_run(const MpmConfig& c, int ranks, std::uint64_t memory_bytes, bool force);

}  // namespace mpmx::app
