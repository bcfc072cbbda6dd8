#pragma once
// Isotherms P(rho) for the MD-to-DPD fit (seed 004 sec. 2.2; VALIDATION.md D0): an MD
// crystal of the atomistic potential at each lattice constant, and the DPDE crystal of
// mesoparticles at the matching coarse lattice constant, each at the isotherm's
// temperature; and the static pressure of the perfect coarse lattice of a pair
// potential, the part of the DPD isotherm that depends on the potential's parameters.
// The densities run on threads (one system each): the same numbers for any count.
#include <cstdint>
#include <vector>

#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::multiscale {

struct IsothermPoint {
  double lattice_constant = 0;  // Angstrom (atomic for MD, coarse for DPD)
  double pressure = 0;          // GPa, time average
  double pressure_error = 0;    // GPa, standard error from 10 blocks
  double temperature = 0;       // K, time average (kinetic)
};

struct MdIsothermOptions {
  int cells = 5;             // fcc cells per edge
  double temperature = 298;  // K
  double dt = 0.002;         // ps
  int equilibrate_steps = 3000;  // velocities rescaled to the temperature every 50 steps,
  int sample_steps = 3000;       // and while sampling the pressure every 10 steps
  std::uint64_t seed = 1;
  int threads = 1;
};

// Mean and standard error of a time series from 10 blocks.
void block_average(const std::vector<double>& samples, double& mean, double& error);

// Velocities scaled about their mean so that the kinetic temperature is `temperature` (K).
void rescale_temperature(md::System& s, double temperature);
// `steps` steps of dt (ps), the velocities rescaled to `temperature` after every 50.
void advance_at_temperature(md::System& s, int steps, double dt, double temperature);
// -(sigma_xx + sigma_yy + sigma_zz) / 3.
double mean_pressure(const particles::Mat3& stress);

std::vector<IsothermPoint> md_isotherm(const md::Potential& pot, const std::vector<double>& lattice_constants,
                                       const MdIsothermOptions& o);

struct DpdIsothermOptions {
  int cells = 4;                // coarse fcc cells per edge
  double temperature = 298;     // K (kinetic and internal)
  double mass = 8 * 63.546;     // amu per mesoparticle
  double gamma = 0.2;           // amu/ps
  double heat_capacity = 0;     // eV/K per mesoparticle (DPDE)
  double dt = 0.005;            // ps
  double skin = 1.0;            // Angstrom
  double berendsen_tau = 0.5;   // ps
  int equilibrate_steps = 1000;  // Berendsen on kinetic and internal temperatures
  int sample_steps = 2000;       // DPDE, NVE, pressure every 10 steps
  std::uint64_t seed = 1;
  int threads = 1;
};

std::vector<IsothermPoint> dpd_isotherm(const dpd::PairPotential& pot,
                                        const std::vector<double>& coarse_lattice_constants,
                                        const DpdIsothermOptions& o);

// Pressure (GPa) of the perfect fcc lattice of constant `a` at rest under the pair
// potential: (1 / 3 Omega) (1/2) sum over lattice vectors R of |R| F(|R|), Omega = a^3/4.
double static_lattice_pressure(const dpd::PairPotential& pot, double a);

// Density (same unit as `densities`) where the pressure crosses zero, by linear
// interpolation between the samples (sorted by density); NaN when it does not cross.
double zero_pressure_density(const std::vector<double>& densities, const std::vector<double>& pressures);

}  // namespace mpmx::multiscale
