#pragma once
// The cubic elastic constants C11 and C12 of a crystal measured as the engines see it:
// periodic fcc boxes strained by +-e along x (positions and box, F = diag(1 + e, 1, 1)),
// the time-averaged Cauchy stress of each, and the central difference (issue targets of
// VALIDATION.md D0: the MD crystal's constants at 298 K, which the isotherm alone leaves
// open). For a state of pressure P the Cauchy slopes hold the prestress,
//   d sigma_xx / de = C11 - P,   d sigma_yy / de = C12 + P,
// with C the second derivatives of the energy per reference volume in the Green strain
// (the Born constants of dpd/elastic.hpp for a pair potential at rest); the constants
// returned are those C, so that a static lattice gives the lattice sums at any density.
// At 0 K the boxes are static (one force evaluation each). At a temperature, MD boxes
// keep it by velocity rescaling every 50 steps (as the isotherm does), DPD ones by DPDE
// after a Berendsen start; the unstrained box is equilibrated once and both strained
// boxes start from it, one thread each: the same numbers for any thread count.
#include <cstdint>

#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/md/elastic_constants.hpp"
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::multiscale {

struct CubicConstants {
  double c11 = 0, c12 = 0;              // GPa
  double c11_error = 0, c12_error = 0;  // GPa, from the stresses' block errors (0 at 0 K)
  double pressure = 0;                  // GPa, of the unstrained state (mean of the two at T > 0)
  double strain = 0;                    // the e used
};

struct StrainedBoxOptions {
  int cells = 5;            // fcc cells per edge (4 n^3 atoms or particles)
  double temperature = 0;   // K; 0: static lattice
  double strain = 0;        // 0: 1e-4 static, 0.01 at a temperature
  double dt = 0.002;        // ps
  int equilibrate_steps = 3000;  // the unstrained box, then half as many for each strained one
  int sample_steps = 5000;       // stress every 10 steps
  std::uint64_t seed = 1;
  int threads = 1;
  // DPD(E) only: mesoparticle mass (amu), gamma (amu/ps), heat capacity (eV/K), Berendsen tau (ps).
  double mass = 8 * 63.546, gamma = 0.2, heat_capacity = 0, berendsen_tau = 0.5;
};

// The full tensor at a temperature (md/elastic_constants.hpp's at 0 K): the crystal
// `spec` (its constant as given: a thermal one, from NPT) of `tiles` equilibrated once at
// o.temperature, then each of the twelve boxes strained by +-e in one Voigt component
// from it, equilibrated for half as long and sampled; C_ij from the time-averaged
// stresses' central differences, each with its error from the block errors.
struct TensorAtTemperature {
  md::Voigt c{}, error{};          // GPa, box frame
  std::array<double, 6> stress{};  // the unstrained box's mean (GPa)
  double strain = 0;
};
TensorAtTemperature md_strained_tensor(const md::Potential& pot, const particles::LatticeSpec& spec,
                                       const std::array<int, 3>& tiles, const StrainedBoxOptions& o);

CubicConstants md_strained_constants(const md::Potential& pot, double lattice_constant, const StrainedBoxOptions& o);
CubicConstants dpd_strained_constants(const dpd::PairPotential& pot, double lattice_constant,
                                      const StrainedBoxOptions& o);

}  // namespace mpmx::multiscale
