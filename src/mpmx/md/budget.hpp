#pragma once
// What an MD deck will cost before it runs: atoms, peak memory, work (atom-steps). A
// deck the machine cannot hold is refused always; one that would run for more than
// about a day is refused unless forced. Both name the key and the figure.
#include <string>

#include "mpmx/md/config.hpp"

namespace mpmx::md {

// mpmx's MD on one core, Cu EAM: 2.1e6-3.2e6 atom-steps/s in an AVX2 -march=native
// build (docs/performance.md), 4e5-5e5 in the portable Release build on a shared core.
// The figure the work limit is scaled by lies between, on the cautious side.
inline constexpr double kMdAtomStepsPerSecond = 1e6;
// About a day of it: the most work a run takes without --force.
inline constexpr double kMdWorkLimit = 86400.0 * kMdAtomStepsPerSecond;

struct MdBudget {
  double atoms = 0;        // atoms of the system (the bar's for a bar deck)
  std::string size_key;    // the key that sets them ("lattice.cells", "bar.cells_x and bar.cells_yz")
  double bytes = 0;        // estimated peak memory
  double atom_steps = 0;   // atoms x (relax_steps + steps), plus one per atom per scan point
  std::string work_key;    // "run.steps" or "thermal.relax_steps + run.steps"
};

// Bytes of one periodic fcc box of n[0] x n[1] x n[2] cells of lattice constant `a`
// whose forces reach `reach` (cutoff + skin), without the program's fixed share: the
// same fit as estimate_md, for the md_closure boxes of a continuum deck.
double box_bytes(const double n[3], double a, double reach);

// Bytes a box holds between the macro steps of a multiscale run (System::compact: its
// atoms' positions, velocities, forces, types and ids, and the box's own small state).
double compact_box_bytes(double atoms);

// `cutoff`: the potential's (Potential::cutoff()).
MdBudget estimate_md(const MdConfig& c, double cutoff);

// Throws InputError when the estimate exceeds `memory_bytes` (always), or the work
// exceeds kMdWorkLimit unless `force`; `memory_bytes` 0: unknown, not checked.
void check_md_budget(const MdBudget& b, std::uint64_t memory_bytes, bool force);

}  // namespace mpmx::md
