#pragma once
// The full elastic tensor of a crystal at 0 K, as the engine sees it: the box of any
// lattice and orientation strained by +-e in each of the six Voigt components (normal
// strains by scaling x, y or z and the box; shears by tilting it, x += e y and so on, the
// engineering strain e), the stress of each, and the central differences
//   C_ij = (sigma_i(+e_j) - sigma_i(-e_j)) / (2 e),   Voigt order xx yy zz yz xz xy,
// which is what LAMMPS's ELASTIC example computes from the same boxes. At a stress-free
// state these are the second derivatives of the energy density; at a prestressed one the
// Cauchy slopes, as LAMMPS's are. A crystal with more than one atom per primitive cell
// (hcp) relaxes its atoms inside each strained box first (`relax`): the relaxed
// constants LAMMPS's ELASTIC example gives after its minimisation; without it, the
// homogeneous (unrelaxed) ones. The tensor in the box frame is also given rotated to the
// crystal's own axes (the cube's for fcc and bcc; LAMMPS's hcp cell, a1 along x, c along
// z), C_abcd = R_ia R_jb R_kc R_ld C'_ijkl with R's rows the orient vectors normalised.
#include <array>

#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

using Voigt = std::array<std::array<double, 6>, 6>;  // GPa

struct ElasticTensor {
  Voigt box{};      // in the box frame (x, y, z the deck's orient rows)
  Voigt crystal{};  // in the crystal's axes
  std::array<double, 6> stress{};  // the unstrained box's (GPa, Voigt order; tension positive)
  double strain = 0;               // the e used
  bool relaxed = false;            // atoms relaxed in each strained box
  double largest_force = 0;        // eV/A left on an atom after the relaxations (0 unrelaxed)
};

struct ElasticOptions {
  double strain = 1e-5;  // small enough that O(e^2) is below 1e-8 of C, large against round-off
  bool relax = true;     // relax the atoms of crystals with a basis (hcp); fcc and bcc need none
  double force_tolerance = 1e-9;  // eV/A: the relaxation's end
};

// The crystal under the engineering strain e in Voigt component j (0-5): x_a += e x_b for
// the component's (a, b), with the box's edge or tilt, so that the image lattice moves
// with the atoms (a periodic box's shear is its tilt, upper triangular as LAMMPS's).
void strain_voigt(Atoms& atoms, Box& box, int j, double e);
// A 3x3 stress as its six Voigt components.
std::array<double, 6> voigt_stress(const Mat3& s);

// `spec.constant` is the lattice constant used; `tiles` the periodic tiles along x, y, z.
ElasticTensor elastic_tensor(const Potential& pot, const particles::LatticeSpec& spec,
                             const std::array<int, 3>& tiles, const ElasticOptions& o = {});

// Whether a cubic or any crystal's tensor is mechanically stable: every eigenvalue of the
// symmetric 6x6 positive (Born's criteria in their general form).
bool born_stable(const Voigt& c);

// R's rows: the orient vectors normalised (hcp's in its cell's Cartesian frame).
std::array<std::array<double, 3>, 3> orientation_matrix(const particles::LatticeSpec& spec);
// C' in the box frame to C in the crystal's: the rotation above.
Voigt rotate_to_crystal(const Voigt& box, const std::array<std::array<double, 3>, 3>& r);

}  // namespace mpmx::md
