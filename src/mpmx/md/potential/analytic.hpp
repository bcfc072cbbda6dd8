#pragma once
// The keys the analytic potentials' [potential] tables share (lj, sutton_chen): the
// energy scale epsilon (eV), the cutoff (Angstrom) and the atoms' mass (amu), each positive.
#include "mpmx/core/table.hpp"

namespace mpmx::md {

inline void read_analytic_scale(Table& t, double& epsilon, double& cutoff, double& mass) {
  epsilon = t.number("epsilon");
  t.positive("epsilon", epsilon);
  cutoff = t.number("cutoff");
  t.positive("cutoff", cutoff);
  mass = t.number("mass");
  t.positive("mass", mass);
}

}  // namespace mpmx::md
