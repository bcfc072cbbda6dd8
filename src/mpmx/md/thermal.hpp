#pragma once
// Thermal initialisation (section 6.2) and energy injection (eq. 7.11).
#include <vector>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// Maxwell speeds at `temperature_K` (the caller passes twice the target, as section 6.2
// does), uniformly distributed directions on the sphere, total momentum removed, then
// scaled so that the kinetic temperature (3N-3 degrees of freedom) is exact.
void maxwell_velocities(Atoms& atoms, const std::vector<double>& type_mass,
                        double temperature_K, RngStream& rng);

// Kinetic energy (eV) about the mean velocity, and the mean velocity itself.
double thermal_kinetic_energy(const Atoms& atoms, const std::vector<double>& type_mass);
double kinetic_temperature(const Atoms& atoms, const std::vector<double>& type_mass);

// Adds `energy_eV` (> -thermal KE) as kinetic energy by scaling the velocities about the
// mean; a box at rest gets random directions from rng first.
void inject_energy(Atoms& atoms, const std::vector<double>& type_mass, double energy_eV,
                   RngStream& rng);

}  // namespace mpmx::md
