#pragma once
// What MD costs in this engine, the figures a run's budget is scaled by: the atom-steps
// a core runs a second, and the bytes of a periodic box, fitted to measured peak memory
// (the MD deck's budget, app/md/budget.hpp, and the md_closure boxes of a continuum deck).
#include <cstdint>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

// mpmx's MD on one core, Cu EAM: 2.1e6-3.2e6 atom-steps/s in an AVX2 -march=native
// build (docs/performance.md), 4e5-5e5 in the portable Release build on a shared core.
// The figure the work limit is scaled by lies between, on the cautious side.
inline constexpr double kMdAtomStepsPerSecond = 1e6;

// Bytes, fitted to the peak RSS of `mpmx md` (Cu EAM, Release): boxes of 500, 32,000
// and 131,072 atoms (14.5, 65 and 221 MB) and a 144,000-atom bar (287 MB, estimate
// within 2%); refitted to the tiled force loop with boxes of 32,000, 131,072 and 340,736
// atoms (86.7, 303 and 743 MB). Per local atom: its fields and copies (300), and per
// pair of its half list the list, its tiled copy and the force passes' pair buffers
// (36); per entry of locals plus ghosts (positions in three layouts, type, owner, image,
// bins, forces, density) 110, and 56 more for a bar's per-atom energy and virial; a
// jet's atom 1,500 more (its records and tiles' per-atom tallies: the s = 0.05 and 0.1
// samples, 28 and 122 MB); the program and potential tables 16 MiB.
inline constexpr double kBytesPerLocal = 300.0;
inline constexpr double kBytesPerPair = 36.0;
inline constexpr double kBytesPerEntry = 110.0;
inline constexpr double kBytesPerEntryPerAtom = 56.0;
inline constexpr double kBytesPerJetAtom = 1500.0;
inline constexpr double kBytesFixed = 16.0 * 1024 * 1024;

// Bytes of one periodic fcc box of n[0] x n[1] x n[2] cells of lattice constant `a`
// whose forces reach `reach` (cutoff + skin), without the program's fixed share: the
// same fit as the MD deck's estimate, for the md_closure boxes of a continuum deck.
double box_bytes(const double n[3], double a, double reach);

// Atom-steps a second of a periodic fcc box of cells^3 cells of lattice constant `a` on
// this core, timed for about a tenth of a second after ten steps that build its lists:
// what a budget scales a run's work by, measured rather than typed in. 0 (the caller takes
// kMdAtomStepsPerSecond) when the box would hold more than kMaxTimedPairs pairs.
inline constexpr double kMaxTimedPairs = 2e6;  // a 500-atom copper box holds 19,000
double measure_atom_steps_per_second(const Potential& pot, const SystemOptions& options, double a, int cells,
                                     double temperature, std::uint64_t seed, double dt);
// The same for any crystal (particles/oriented_lattice), `tiles` per axis; its pairs
// estimated as those of the fcc box of its atoms and density.
double measure_atom_steps_per_second(const Potential& pot, const SystemOptions& options,
                                     const particles::LatticeSpec& lattice, int tiles, double temperature,
                                     std::uint64_t seed, double dt);

// Bytes of a box's atoms (positions, velocities, forces, types and ids) and of its own
// small state.
double compact_box_bytes(double atoms);
// Bytes a box of cells^3 fcc cells of lattice constant `a` holds between the macro steps
// of a multiscale run (System::compact): its atoms, and the neighbour list it keeps for
// the next macro step (the half list within `reach` = cutoff + skin, the ghosts' owners
// and images, the positions at the list's build).
double kept_box_bytes(double cells, double a, double reach);

}  // namespace mpmx::md
