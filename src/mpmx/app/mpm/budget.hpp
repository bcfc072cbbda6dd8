#pragma once
// What a continuum deck will cost before it runs: points, grid nodes, md_closure atoms,
// peak memory and work. As for MD decks (md/budget.hpp), a deck the machine cannot hold
// is refused always, and one that would run for more than about a day unless forced;
// both name the key and the figure. `mpmx check` and `mpmx run` both apply it.
#include <cstdint>
#include <string>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// Point-steps per second on one core, on the cautious side of docs/performance.md:
// 1-D runs 5e7-1.9e8 (fused kernels), 2-D and 3-D 0.9e6-6.6e6; a sub-point costs about
// as much as a point. The typical figures, for decks of under a minute by them; a longer
// one is estimated at the rate its own scheme and law are timed at here (point_rate.hpp).
inline constexpr double kPointSteps1dPerSecond = 2e7;
inline constexpr double kPointStepsPerSecond = 5e5;
inline constexpr double kTimeRateAboveSeconds = 60.0;
// A day of work: the most a run takes without --force.
inline constexpr double kWorkLimitSeconds = 86400.0;

struct MpmBudget {
  double points = 0;       // material points: counted through the bodies up to 1e7 lattice sites, else every cell filled
  double subpoints = 1;    // integration points per point (ddmp_subpoints)
  double nodes = 0;        // grid nodes
  double md_atoms_per_point = 0;  // md_closure: atoms of each point's box
  double md_atoms = 0;     // md_closure: atoms of all the points' boxes
  double md_bytes_per_atom = 0;  // md_closure: bytes a box keeps per atom between macro steps
  double md_atom_steps = 0;  // md_closure: those atoms x (relaxation + MD steps of the run), all ranks
  double md_rate = 0;             // md_closure: the atom-steps a second of one core the work is scaled by
  bool md_rate_measured = false;  // that rate timed on this machine (PointCost), not the typical figure
  int ranks = 1;           // the boxes spread over so many ranks: bytes and seconds are one rank's
  double bytes = 0;        // estimated peak memory
  double seconds = 0;      // estimated wall time on one core
  double point_rate = 0;   // the continuum's point-steps a second of one core the work is scaled by
  bool point_rate_measured = false;  // that rate timed on this machine for this deck, not the typical figure
  double steps = 0;         // one grid's (a study: its finest)
  std::string size_key;    // the key the largest memory share comes from
  std::string deck;        // the deck's path, for the refusal's message
  std::string work_key = "time.end / time.dt";  // the keys the work comes from
  int levels = 1;          // convergence.levels: memory the finest grid's, work (seconds, md_atom_steps) all grids'
};

// `ranks`: the MPI ranks the md_closure boxes spread over (each holds and advances
// 1/ranks of them; the continuum is on every rank): the figures are one rank's.
MpmBudget estimate_mpm(const MpmConfig& c, int ranks = 1);

// Throws InputError when the estimate exceeds `memory_bytes` (always; 0: unknown, not
// checked) or the work a day unless `force`.
void check_mpm_budget(const MpmBudget& b, std::uint64_t memory_bytes, bool force);

}  // namespace mpmx::app
