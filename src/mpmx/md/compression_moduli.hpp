#pragma once
// The tangent moduli of a potential's perfect 0 K crystal compressed far from its
// equilibrium, tabulated against J = V / V0: what a material point whose stress comes
// from an MD box of that crystal (md_closure) answers a small further strain with, so that
// its wave speed, and the continuum step it allows, follow its compression (theory.md,
// "The time step"). At each J three states of the crystal, each the homogeneous strain of
// the small box elastic_constants.hpp uses (hcp's basis unrelaxed):
//   uniaxial along axis a (its length times J):  M_a = d sigma_aa / d ln L_a,
//   hydrostatic (every length times J^(1/3)):    K = -dp / d ln V, and
//                                                M_h,a = d sigma_aa / d ln L_a there,
// each by central differences of the virial stress (eq. 2.25) over +-1e-4 in ln L. The
// largest of the seven is the law's stiffness at J: the shocked state of a point lies
// between the elastic (uniaxial) and the plastically relaxed (hydrostatic) one, and the
// fastest wave is the longitudinal one of whichever is stiffer. Below J = 1 the table
// keeps the largest between J and 1 (the lattice's path softens locally; a point
// compressed to J passed the stiffer states).
#include <array>
#include <vector>

#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

struct CompressionModuli {
  std::vector<double> J;                          // ascending, V / V0
  std::vector<double> modulus;                    // GPa: the largest of the seven at each J (above)
  std::array<std::vector<double>, 3> uniaxial;    // GPa: -sigma_aa under uniaxial J along a (compression positive)
  std::array<std::vector<double>, 3> uniaxial_modulus;  // GPa: M_a above
  double modulus_at(double j) const;              // linear in J between rows, the end rows' beyond
  // A planar shock along axis a driven at particle speed up into the crystal of density
  // rho0 (continuum units in, `gpa_per_unit` GPa a continuum stress unit): the compression
  // where the Rayleigh line P = rho0 up^2 / (1 - J) meets the uniaxial curve, the largest
  // such J (the first reached); NaN where none lies in the table.
  double shock_compression(int axis, double up, double rho0, double gpa_per_unit) const;
};

// `spec.constant` is the 0 K lattice constant; J from j_min to j_max in `rows` rows.
CompressionModuli compression_moduli(const Potential& pot, const particles::LatticeSpec& spec, double j_min = 0.5,
                                     double j_max = 1.2, int rows = 71);

}  // namespace mpmx::md
