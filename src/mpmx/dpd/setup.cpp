#include "mpmx/dpd/setup.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/pair_random.hpp"
#include "mpmx/dpd/thermostat.hpp"

namespace mpmx::dpd {

Particles fcc_block(const std::array<int, 3>& cells, double a, const particles::Vec3& origin, double mass, int type,
                    std::int64_t first_id) {
  if (cells[0] < 1 || cells[1] < 1 || cells[2] < 1 || !(a > 0.0))
    throw InputError(fmt::format("fcc block: cells {}x{}x{}, a = {}: need cells >= 1 and a > 0", cells[0], cells[1],
                                 cells[2], a));
  Particles p;
  std::int64_t id = first_id;
  fcc_sites(cells, a, origin, [&](double x, double y, double z) { p.push_back(x, y, z, mass, type, id++); });
  return p;
}

Particles random_block(long count, const particles::Vec3& size, const particles::Vec3& origin, double mass, int type,
                       std::int64_t first_id, std::uint64_t seed) {
  if (count < 0 || !(size[0] > 0 && size[1] > 0 && size[2] > 0))
    throw InputError(fmt::format("random block: count {} in {} x {} x {}: need count >= 0 and a positive size",
                                 count, size[0], size[1], size[2]));
  Particles p;
  std::int64_t id = first_id;
  random_sites(count, size, origin, seed, [&](double x, double y, double z) { p.push_back(x, y, z, mass, type, id++); });
  return p;
}

void append(Particles& a, const Particles& b) {
  for (std::size_t i = 0; i < b.size(); ++i) {
    a.push_back(b.x[i], b.y[i], b.z[i], b.mass[i], b.type[i], b.id[i]);
    const std::size_t k = a.size() - 1;
    a.vx[k] = b.vx[i], a.vy[k] = b.vy[i], a.vz[k] = b.vz[i];
    a.u[k] = b.u[i];
    a.group[k] = b.group[i];
  }
}

void maxwell_velocities(Particles& p, double temperature_K, std::uint64_t seed) {
  if (!(temperature_K >= 0)) throw InputError(fmt::format("temperature = {} K: must be >= 0", temperature_K));
  double mt = 0, px = 0, py = 0, pz = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.rigid(i)) continue;
    // Three normal components from the particle's own stream: independent of order.
    particles::RngStream rng(seed, mix64(static_cast<std::uint64_t>(p.id[i])));
    const double sd = std::sqrt(units::boltzmann_eV_per_K * temperature_K / (p.mass[i] * units::mvv2e));
    p.vx[i] = sd * rng.normal(), p.vy[i] = sd * rng.normal(), p.vz[i] = sd * rng.normal();
    mt += p.mass[i], px += p.mass[i] * p.vx[i], py += p.mass[i] * p.vy[i], pz += p.mass[i] * p.vz[i];
  }
  if (mt == 0) return;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.rigid(i)) continue;
    p.vx[i] -= px / mt, p.vy[i] -= py / mt, p.vz[i] -= pz / mt;
  }
  const double t = kinetic_temperature(p);
  if (t > 0) {
    const double s = std::sqrt(temperature_K / t);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (p.rigid(i)) continue;
      p.vx[i] *= s, p.vy[i] *= s, p.vz[i] *= s;
    }
  }
}

}  // namespace mpmx::dpd
