#pragma once
// The 0 K fcc crystal of a potential: the lattice constant of least energy (where the
// virial pressure vanishes; section 6.2 builds every material point's box at it) and
// the uniaxial-strain modulus C11 there (the slope of fig. 5.4, case M4), with C12 and
// C44: the cubic constants a continuum law (cubic_elastic) takes from the potential.
#include "mpmx/md/potential/potential.hpp"

namespace mpmx::md {

struct FccEquilibrium {
  double lattice_constant = 0.0;  // Angstrom
  double energy_per_atom = 0.0;   // eV
  double c11_gpa = 0.0;           // d sigma_xx / d e_xx at zero strain
  double c12_gpa = 0.0;           // d sigma_yy / d e_xx
  double c44_gpa = 0.0;           // d sigma_xy / d gamma_xy (engineering shear)
  double density_amu_per_A3 = 0.0;
};

// Throws RunError when no minimum lies between 0.5 and 3 times the potential's cutoff.
FccEquilibrium fcc_equilibrium(const Potential& potential);

}  // namespace mpmx::md
