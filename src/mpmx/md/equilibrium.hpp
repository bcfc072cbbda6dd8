#pragma once
// The 0 K crystal of a potential: the lattice constant of least energy (where the virial
// pressure vanishes; section 6.2 builds every material point's box at it) and the
// uniaxial-strain modulus C11 there (the slope of fig. 5.4, case M4), with C12 and C44:
// the constants a continuum law (cubic_elastic) takes from the potential. For an oriented
// crystal (M6) they are the box frame's: C11 = d sigma_xx / d e_xx along the box's x, and
// so on. The strains are homogeneous: hcp's two sublattices are not relaxed against each
// other (the unrelaxed constants, what LAMMPS gives for the same strained box).
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

struct FccEquilibrium {
  double lattice_constant = 0.0;  // Angstrom
  double energy_per_atom = 0.0;   // eV
  double c11_gpa = 0.0;           // d sigma_xx / d e_xx at zero strain
  double c12_gpa = 0.0;           // d sigma_yy / d e_xx
  double c44_gpa = 0.0;           // d sigma_xy / d gamma_xy (engineering shear)
  double density_amu_per_A3 = 0.0;
};
using CrystalEquilibrium = FccEquilibrium;

// Throws RunError when no minimum lies between 0.5 and 3 times the potential's cutoff.
FccEquilibrium fcc_equilibrium(const Potential& potential);

// The same for any lattice and orientation (shape.constant is not read; hcp keeps its
// c/a): a scanned over the range whose nearest neighbours fcc's scan spans.
CrystalEquilibrium lattice_equilibrium(const Potential& potential, const particles::LatticeSpec& shape);

// The periodic tiles of `shape` that make a box at least two lattice constants on every
// edge (the small box the equilibrium is computed on).
std::array<int, 3> equilibrium_tiles(const particles::LatticeSpec& shape);

}  // namespace mpmx::md
