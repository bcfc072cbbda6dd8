#pragma once
// The totals of a state the run's energy and momentum balance reads: kinetic energy,
// momentum, sum m|v|, the laws' stored energy, mass. The same sums for any thread count.
#include <array>

#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

struct Sums {
  double kinetic = 0.0, abs_momentum = 0.0, internal = 0.0, mass = 0.0;
  std::array<double, 3> momentum{};
};

// 1-D keeps ADMPM's stored energy of the elastic bar (eq. 8.26) and no other
// (Material::stored_energy_in_1d).
template <int Dim>
Sums sums(const State<Dim>& s);

}  // namespace mpmx::mpm
