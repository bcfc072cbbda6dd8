#include "mpmx/md/budget.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "mpmx/particles/lattice.hpp"

namespace mpmx::md {

double box_bytes(const double n[3], double a, double reach) {
  const double atoms = 4.0 * n[0] * n[1] * n[2], density = 4.0 / (a * a * a);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * a + 2.0 * reach;
  entries = std::max(entries, atoms);
  const double pairs = atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  return kBytesPerLocal * atoms + kBytesPerEntry * entries + kBytesPerPair * pairs;
}

double measure_atom_steps_per_second(const Potential& pot, const SystemOptions& options, double a, int cells,
                                     double temperature, std::uint64_t seed, double dt) {
  // Timed only where the box is cheap to build: its pairs from the counts first (a deck
  // whose cutoff holds thousands of neighbours would spend minutes and gigabytes here).
  const double reach = pot.cutoff() + options.skin, atoms = 4.0 * cells * cells * cells;
  const double pairs = atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * 4.0 / (a * a * a);
  if (!(pairs <= kMaxTimedPairs)) return 0.0;
  System box(fcc(cells, cells, cells, a, 0.0), pot, options);
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

double compact_box_bytes(double atoms) {
  constexpr double kBytesPerAtom = 9 * 8 + 4 + 8;  // x, v, f; type; id
  constexpr double kBytesPerBox = 2048;            // the System itself, its vectors and stream
  return kBytesPerAtom * atoms + kBytesPerBox;
}

double kept_box_bytes(double cells, double a, double reach) {
  const double atoms = 4.0 * cells * cells * cells, density = 4.0 / (a * a * a);
  const double side = cells * a + 2.0 * reach;
  const double entries = std::max(atoms, density * side * side * side);
  const double pairs = atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  constexpr double kListPerAtom = 3 * 8 + 4;  // positions at the build; the list's offsets
  constexpr double kPerPair = 4;               // an entry's index
  constexpr double kPerEntry = 4 + 4 + 3;      // type, owner, image
  return compact_box_bytes(atoms) + kListPerAtom * atoms + kPerPair * pairs + kPerEntry * entries;
}

}  // namespace mpmx::md
