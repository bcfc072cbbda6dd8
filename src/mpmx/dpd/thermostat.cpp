#include "mpmx/dpd/thermostat.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "mpmx/core/units.hpp"

namespace mpmx::dpd {

namespace {
struct Thermal {
  std::array<double, 3> mean{};
  double ke2 = 0;  // sum m |v - mean|^2, amu Angstrom^2/ps^2
  long count = 0;
};

Thermal thermal(const Particles& p) {
  Thermal t;
  double mt = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.rigid(i)) continue;
    t.mean[0] += p.mass[i] * p.vx[i], t.mean[1] += p.mass[i] * p.vy[i], t.mean[2] += p.mass[i] * p.vz[i];
    mt += p.mass[i];
    ++t.count;
  }
  if (mt > 0)
    for (auto& m : t.mean) m /= mt;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.rigid(i)) continue;
    const double dx = p.vx[i] - t.mean[0], dy = p.vy[i] - t.mean[1], dz = p.vz[i] - t.mean[2];
    t.ke2 += p.mass[i] * (dx * dx + dy * dy + dz * dz);
  }
  return t;
}
}  // namespace

double kinetic_temperature(const Particles& p) {
  const Thermal t = thermal(p);
  const double dof = t.count > 1 ? 3.0 * t.count - 3.0 : 3.0;
  return t.ke2 * units::mvv2e / (dof * units::boltzmann_eV_per_K);
}

void berendsen_rescale(Particles& p, const Berendsen& b, double dt, double heat_capacity) {
  const Thermal t = thermal(p);
  const double dof = t.count > 1 ? 3.0 * t.count - 3.0 : 3.0;
  const double temp = t.ke2 * units::mvv2e / (dof * units::boltzmann_eV_per_K);
  if (temp > 0) {
    const double lambda = std::sqrt(std::max(0.0, 1.0 + dt / b.tau * (b.temperature / temp - 1.0)));
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.rigid(i)) continue;
      p.vx[i] = t.mean[0] + lambda * (p.vx[i] - t.mean[0]);
      p.vy[i] = t.mean[1] + lambda * (p.vy[i] - t.mean[1]);
      p.vz[i] = t.mean[2] + lambda * (p.vz[i] - t.mean[2]);
    }
  }
  if (heat_capacity > 0) {
    const double target = heat_capacity * b.temperature, f = std::min(1.0, dt / b.tau);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!p.rigid(i)) p.u[i] += f * (target - p.u[i]);
  }
}

}  // namespace mpmx::dpd
