#include "mpmx/md/forces.hpp"

#include <algorithm>

namespace mpmx::md {

void ForceWork::reset(int nall) {
  const auto n = static_cast<std::size_t>(nall);
  for (auto* v : {&fx, &fy, &fz, &rho, &fp}) {
    v->resize(n);
    std::fill(v->begin(), v->end(), 0.0);
  }
  if (per_atom) {
    energy_atom.assign(n, 0.0);
    virial_atom.assign(6 * n, 0.0);
  }
}

}  // namespace mpmx::md
