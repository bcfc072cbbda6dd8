#include "mpmx/md/forces.hpp"

#include <algorithm>

namespace mpmx::md {

void ForceWork::reset(int nall) {
  const auto n = static_cast<std::size_t>(nall);
  for (auto* v : {&fx, &fy, &fz, &fp}) v->resize(n);
  rho.assign(n, 0.0);
  folded = false;
  if (per_atom) {
    energy_atom.assign(n, 0.0);
    virial_atom.assign(6 * n, 0.0);
  }
}

void ForceWork::zero_forces() {
  std::fill(fx.begin(), fx.end(), 0.0);
  std::fill(fy.begin(), fy.end(), 0.0);
  std::fill(fz.begin(), fz.end(), 0.0);
}

}  // namespace mpmx::md
