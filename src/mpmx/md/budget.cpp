#include "mpmx/md/budget.hpp"

#include <algorithm>
#include <cmath>

namespace mpmx::md {

double box_bytes(const double n[3], double a, double reach) {
  const double atoms = 4.0 * n[0] * n[1] * n[2], density = 4.0 / (a * a * a);
  double entries = density;
  for (int d = 0; d < 3; ++d) entries *= n[d] * a + 2.0 * reach;
  entries = std::max(entries, atoms);
  const double pairs = atoms * 0.5 * (4.0 / 3.0) * M_PI * reach * reach * reach * density;
  return kBytesPerLocal * atoms + kBytesPerEntry * entries + kBytesPerPair * pairs;
}

double compact_box_bytes(double atoms) {
  constexpr double kBytesPerAtom = 9 * 8 + 4 + 8;  // x, v, f; type; id
  constexpr double kBytesPerBox = 2048;            // the System itself, its vectors and stream
  return kBytesPerAtom * atoms + kBytesPerBox;
}

}  // namespace mpmx::md
