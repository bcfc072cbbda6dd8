#include "mpmx/md/integrate.hpp"

#include <algorithm>

#include "mpmx/core/units.hpp"

namespace mpmx::md {

void kick(Atoms& a, const std::vector<double>& mass, double dt, double factor, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.size());
  if (mass.size() == 1) {  // one type: no per-atom lookup
    const double c = factor * dt * units::ftm2v / mass[0];
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      a.vx[i] += c * a.fx[i];
      a.vy[i] += c * a.fy[i];
      a.vz[i] += c * a.fz[i];
    }
    return;
  }
  std::vector<double> inv(mass.size());
  for (std::size_t t = 0; t < mass.size(); ++t) inv[t] = factor * dt * units::ftm2v / mass[t];
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double c = inv[a.type[i]];
    a.vx[i] += c * a.fx[i];
    a.vy[i] += c * a.fy[i];
    a.vz[i] += c * a.fz[i];
  }
}

void drift(Atoms& a, double dt, const Mat3& g, bool streaming, int threads) {
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.size());
  if (!streaming) {
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      a.x[i] += dt * a.vx[i];
      a.y[i] += dt * a.vy[i];
      a.z[i] += dt * a.vz[i];
    }
    return;
  }
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double x = a.x[i], y = a.y[i], z = a.z[i];
    a.x[i] += dt * (a.vx[i] + g[0] * x + g[1] * y + g[2] * z);
    a.y[i] += dt * (a.vy[i] + g[4] * y + g[5] * z);
    a.z[i] += dt * (a.vz[i] + g[8] * z);
  }
}

int wrap(Atoms& a, const Box& box, const Mat3& g, bool adjust, int threads) {
  int moved = 0;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(a.size());
#pragma omp parallel for schedule(static) reduction(+ : moved) num_threads(threads) if (threads > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    bool any = false;
    // A second pass catches a coordinate that round-off left at exactly L.
    for (int pass = 0; pass < 3; ++pass) {
      const auto n = box.image_of(a.x[i], a.y[i], a.z[i]);
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) break;
      const Vec3 s = box.shift(n[0], n[1], n[2]);
      a.x[i] -= s[0];
      a.y[i] -= s[1];
      a.z[i] -= s[2];
      if (adjust) {
        a.vx[i] -= g[0] * s[0] + g[1] * s[1] + g[2] * s[2];
        a.vy[i] -= g[4] * s[1] + g[5] * s[2];
        a.vz[i] -= g[8] * s[2];
      }
      any = true;
    }
    moved += any;
  }
  return moved;
}

}  // namespace mpmx::md
