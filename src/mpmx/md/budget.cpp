#include "mpmx/md/budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mpmx/particles/lattice.hpp"

namespace mpmx::md {

namespace {

// An fcc box of n[0] x n[1] x n[2] cells of lattice constant `a` whose pairs reach `reach`:
// its atoms, its entries (atoms and the ghosts within reach of the box) and its half
// list's pairs, from the counts alone.
struct BoxCounts {
  double atoms, entries, pairs;
};
BoxCounts fcc_box_counts(const double n[3], double a, double reach) {
  const double atoms = 4.0 * n[0] * n[1] * n[2], density = 4.0 / (a * a * a);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * a + 2.0 * reach;
  return {atoms, std::max(entries, atoms), atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density};
}

}  // namespace

double box_bytes(const double n[3], double a, double reach) {
  const BoxCounts c = fcc_box_counts(n, a, reach);
  return kBytesPerLocal * c.atoms + kBytesPerEntry * c.entries + kBytesPerPair * c.pairs;
}

namespace {

// Steps `box` for about a tenth of a second after ten that build its lists.
double time_box(System& box, double temperature, std::uint64_t seed, double dt) {
  if (temperature > 0) box.thermalize(temperature, seed, 0);
  box.advance(10, dt);
  const auto t0 = std::chrono::steady_clock::now();
  std::int64_t steps = 0;
  double seconds = 0.0;
  while (seconds < 0.1 && steps < 100000) {
    box.advance(20, dt);
    steps += 20;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return seconds > 0 ? static_cast<double>(steps) * static_cast<double>(box.atoms().size()) / seconds : 0.0;
}

}  // namespace

double measure_atom_steps_per_second(const Potential& pot, const SystemOptions& options, double a, int cells,
                                     double temperature, std::uint64_t seed, double dt) {
  // Timed only where the box is cheap to build: its pairs from the counts first (a deck
  // whose cutoff holds thousands of neighbours would spend minutes and gigabytes here).
  const double n[3] = {double(cells), double(cells), double(cells)};
  const double pairs = fcc_box_counts(n, a, pot.cutoff() + options.skin).pairs;
  if (!(pairs <= kMaxTimedPairs)) return 0.0;
  System box(fcc(cells, cells, cells, a, 0.0), pot, options);
  return time_box(box, temperature, seed, dt);
}

double measure_atom_steps_per_second(const Potential& pot, const SystemOptions& options,
                                     const particles::LatticeSpec& lattice, int tiles, double temperature,
                                     std::uint64_t seed, double dt) {
  if (lattice.plain_fcc())
    return measure_atom_steps_per_second(pot, options, lattice.constant, tiles, temperature, seed, dt);
  const particles::LatticeTile tile = particles::lattice_tile(lattice);
  const double atoms = static_cast<double>(tile.atoms) * tiles * tiles * tiles;
  const double volume = tile.length[0] * tile.length[1] * tile.length[2] * tiles * tiles * tiles;
  const double cells = std::cbrt(atoms / 4.0), a = std::cbrt(4.0 * volume / atoms);  // fcc of its atoms, density
  const double n[3] = {cells, cells, cells};
  if (!(fcc_box_counts(n, a, pot.cutoff() + options.skin).pairs <= kMaxTimedPairs)) return 0.0;
  System box(particles::oriented_crystal(lattice, {tiles, tiles, tiles}), pot, options);
  return time_box(box, temperature, seed, dt);
}

double compact_box_bytes(double atoms) {
  constexpr double kBytesPerAtom = 9 * 8 + 4 + 8;  // x, v, f; type; id
  constexpr double kBytesPerBox = 2048;            // the System itself, its vectors and stream
  return kBytesPerAtom * atoms + kBytesPerBox;
}

double kept_box_bytes(double cells, double a, double reach) {
  const double n[3] = {cells, cells, cells};
  const BoxCounts c = fcc_box_counts(n, a, reach);
  constexpr double kListPerAtom = 3 * 8 + 4;  // positions at the build; the list's offsets
  constexpr double kPerPair = 4;               // an entry's index
  constexpr double kPerEntry = 4 + 4 + 3;      // type, owner, image
  return compact_box_bytes(c.atoms) + kListPerAtom * c.atoms + kPerPair * c.pairs + kPerEntry * c.entries;
}

}  // namespace mpmx::md
