#include "mpmx/md/bins2d.hpp"

#include <cmath>

#include "mpmx/core/units.hpp"

namespace mpmx::md {

namespace {

// The sums of one bin; its fields follow from them (sum m (v - v~)(v - v~) =
// sum m v v - M v~ v~ with v~ = P / M).
struct Sums {
  int n = 0;
  double m = 0, p[3] = {0, 0, 0}, mvv[6] = {0, 0, 0, 0, 0, 0}, w[6] = {0, 0, 0, 0, 0, 0};
};

BinFields finish(const std::vector<Sums>& sums, const BinGrid& g) {
  BinFields f;
  f.grid = g;
  const std::size_t n = sums.size();
  f.atoms.resize(n), f.mass.resize(n), f.vx.resize(n), f.vy.resize(n), f.vz.resize(n);
  f.stress.resize(n), f.temperature.resize(n);
  const double volume = g.volume();
  const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
  for (std::size_t k = 0; k < n; ++k) {
    const Sums& s = sums[k];
    const double v[3] = {s.m > 0 ? s.p[0] / s.m : 0, s.m > 0 ? s.p[1] / s.m : 0, s.m > 0 ? s.p[2] / s.m : 0};
    double kin[6], st[6];
    for (int c = 0; c < 6; ++c) kin[c] = (s.mvv[c] - s.m * v[a[c]] * v[b[c]]) * units::mvv2e;
    for (int c = 0; c < 6; ++c) st[c] = -(kin[c] + s.w[c]) / volume;  // eq. 2.25
    f.atoms[k] = s.n;
    f.mass[k] = s.m;
    f.vx[k] = v[0], f.vy[k] = v[1], f.vz[k] = v[2];
    f.stress[k] = {st[0], st[3], st[4], st[3], st[1], st[5], st[4], st[5], st[2]};
    f.temperature[k] = s.n > 1 ? (kin[0] + kin[1] + kin[2]) / (3.0 * (s.n - 1) * units::boltzmann_eV_per_K) : 0.0;
  }
  return f;
}

}  // namespace

double BinFields::density_g_cm3(int b) const {
  return mass[b] * units::amu_in_kg * 1e3 / (grid.volume() * 1e-24);  // amu / A^3 -> g / cm^3
}

BinFields bin_fields(const Atoms& at, const std::vector<double>& type_mass, const std::vector<double>& w,
                     const BinGrid& g) {
  std::vector<Sums> sums(static_cast<std::size_t>(g.nx) * g.ny);
  const double ly = g.ny * g.dy;
  for (std::size_t i = 0; i < at.size(); ++i) {
    const double u = (at.x[i] - g.x0) / g.dx;
    if (!(u >= 0 && u < g.nx)) continue;
    const double yf = at.y[i] / ly - std::floor(at.y[i] / ly);  // periodic wrap into [0, 1)
    const int ix = static_cast<int>(u);
    const int iy = std::min(static_cast<int>(yf * g.ny), g.ny - 1);
    Sums& s = sums[ix + static_cast<std::size_t>(g.nx) * iy];
    const double m = type_mass[at.type[i]], vx = at.vx[i], vy = at.vy[i], vz = at.vz[i];
    ++s.n;
    s.m += m;
    s.p[0] += m * vx, s.p[1] += m * vy, s.p[2] += m * vz;
    s.mvv[0] += m * vx * vx, s.mvv[1] += m * vy * vy, s.mvv[2] += m * vz * vz;
    s.mvv[3] += m * vx * vy, s.mvv[4] += m * vx * vz, s.mvv[5] += m * vy * vz;
    for (int c = 0; c < 6; ++c) s.w[c] += w[6 * i + c];
  }
  return finish(sums, g);
}

}  // namespace mpmx::md
