#pragma once
// The keys the analytic potentials' [potential] tables share (lj, sutton_chen): the
// energy scale epsilon (eV), the cutoff (Angstrom), each positive, and the atoms' mass
// (amu), an atom's (md/physical_bounds.hpp).
#include "mpmx/core/table.hpp"
#include "mpmx/md/physical_bounds.hpp"

namespace mpmx::md {

inline void read_analytic_scale(Table& t, double& epsilon, double& cutoff, double& mass) {
  epsilon = t.number("epsilon");
  t.positive("epsilon", epsilon);
  cutoff = t.number("cutoff");
  t.positive("cutoff", cutoff);
  mass = t.number("mass");
  if (const std::string why = atom_mass_problem(mass); !why.empty()) t.check(false, "mass", why);
}

}  // namespace mpmx::md
