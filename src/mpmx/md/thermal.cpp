#include "mpmx/md/thermal.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::md {

namespace {
std::array<double, 3> mean_velocity(const Atoms& a, const std::vector<double>& mass) {
  double px = 0, py = 0, pz = 0, mt = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double m = mass[a.type[i]];
    px += m * a.vx[i], py += m * a.vy[i], pz += m * a.vz[i], mt += m;
  }
  if (mt == 0) return {0, 0, 0};
  return {px / mt, py / mt, pz / mt};
}

void remove_mean(Atoms& a, const std::vector<double>& mass) {
  const auto v = mean_velocity(a, mass);
  for (std::size_t i = 0; i < a.size(); ++i) a.vx[i] -= v[0], a.vy[i] -= v[1], a.vz[i] -= v[2];
}

void scale_about_mean(Atoms& a, const std::array<double, 3>& v, double s) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    a.vx[i] = v[0] + s * (a.vx[i] - v[0]);
    a.vy[i] = v[1] + s * (a.vy[i] - v[1]);
    a.vz[i] = v[2] + s * (a.vz[i] - v[2]);
  }
}

double dof(const Atoms& a) { return a.size() > 1 ? 3.0 * a.size() - 3.0 : 3.0; }
}  // namespace

double thermal_kinetic_energy(const Atoms& a, const std::vector<double>& mass) {
  const auto v = mean_velocity(a, mass);
  double ke = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double dx = a.vx[i] - v[0], dy = a.vy[i] - v[1], dz = a.vz[i] - v[2];
    ke += mass[a.type[i]] * (dx * dx + dy * dy + dz * dz);
  }
  return 0.5 * ke * units::mvv2e;
}

double kinetic_temperature(const Atoms& a, const std::vector<double>& mass) {
  return 2.0 * thermal_kinetic_energy(a, mass) / (dof(a) * units::boltzmann_eV_per_K);
}

void maxwell_velocities(Atoms& a, const std::vector<double>& mass, double T, RngStream& rng) {
  if (!(T >= 0)) throw InputError(fmt::format("temperature = {} K: must be >= 0", T));
  for (std::size_t i = 0; i < a.size(); ++i) {
    // Maxwell speed: norm of three normal components of variance kT/m (in A/ps).
    const double sd = std::sqrt(units::boltzmann_eV_per_K * T / (mass[a.type[i]] * units::mvv2e));
    const double g1 = rng.normal(), g2 = rng.normal(), g3 = rng.normal();
    const double speed = sd * std::sqrt(g1 * g1 + g2 * g2 + g3 * g3);
    // Isotropic direction: uniform cos(theta) and phi over the solid angle.
    const double ct = 2.0 * rng.uniform() - 1.0, st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
    const double ph = 2.0 * std::numbers::pi * rng.uniform();
    a.vx[i] = speed * st * std::cos(ph);
    a.vy[i] = speed * st * std::sin(ph);
    a.vz[i] = speed * ct;
  }
  remove_mean(a, mass);
  const double ke = thermal_kinetic_energy(a, mass);
  const double want = 0.5 * dof(a) * units::boltzmann_eV_per_K * T;
  if (ke > 0) scale_about_mean(a, {0, 0, 0}, std::sqrt(want / ke));
}

void inject_energy(Atoms& a, const std::vector<double>& mass, double e, RngStream& rng) {
  double ke = thermal_kinetic_energy(a, mass);
  if (ke + e < 0)
    throw RunError(fmt::format("cannot remove {} eV: the box has only {} eV of thermal kinetic energy",
                               -e, ke));
  const auto v = mean_velocity(a, mass);
  if (ke == 0) {
    if (e == 0) return;
    for (std::size_t i = 0; i < a.size(); ++i)
      a.vx[i] = v[0] + rng.normal(), a.vy[i] = v[1] + rng.normal(), a.vz[i] = v[2] + rng.normal();
    const auto w = mean_velocity(a, mass);
    for (std::size_t i = 0; i < a.size(); ++i)
      a.vx[i] += v[0] - w[0], a.vy[i] += v[1] - w[1], a.vz[i] += v[2] - w[2];
    ke = thermal_kinetic_energy(a, mass);
    scale_about_mean(a, v, std::sqrt(e / ke));
    return;
  }
  scale_about_mean(a, v, std::sqrt((ke + e) / ke));
}

}  // namespace mpmx::md
