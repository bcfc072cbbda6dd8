#pragma once
// What an MD deck will cost before it runs: atoms, peak memory, work (atom-steps). A
// deck the machine cannot hold is refused always; one that would run for more than
// about a day is refused unless forced. Both name the key and the figure.
#include <cstdint>
#include <string>

#include "mpmx/app/md/config.hpp"
#include "mpmx/md/budget.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

// About a day of MD on one core: the most work a run takes without --force.
inline constexpr double kMdWorkLimit = 86400.0 * kMdAtomStepsPerSecond;

struct MdBudget {
  double atoms = 0;        // atoms of the system (the bar's for a bar deck)
  std::string size_key;    // the key that sets them ("lattice.cells", "bar.cells_x and bar.cells_yz")
  double bytes = 0;        // estimated peak memory
  double atom_steps = 0;   // atoms x (relax_steps + steps), plus one per atom per scan point
  std::string work_key;    // "run.steps" or "thermal.relax_steps + run.steps"
  double bins = 0;         // a jet's bins (0: none)
  double output_bytes = 0; // a jet's bin tables and images over every record (about 230 bytes a bin)
  double images = 0;       // cutoff + skin over the shortest box edge: the periodic images a ghost layer spans
};

// The most box lengths the forces may reach across (particles/neighbor.cpp stores an
// atom's image in 8 bits, up to 127; the rest is room for the box's strain).
inline constexpr double kMaxImages = 100;

// `cutoff`: the potential's (Potential::cutoff()).
MdBudget estimate_md(const MdConfig& c, double cutoff);

// Throws InputError when the estimate exceeds `memory_bytes` (always), or the work
// exceeds kMdWorkLimit unless `force`; `memory_bytes` 0: unknown, not checked.
void check_md_budget(const MdBudget& b, std::uint64_t memory_bytes, bool force);

}  // namespace mpmx::app::md
