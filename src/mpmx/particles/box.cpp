#include "mpmx/particles/box.hpp"

#include <cmath>

namespace mpmx::particles {

Mat3 upper_triangular(const Mat3& g) {
  // Exx 2Exy 2Exz / 0 Eyy 2Eyz / 0 0 Ezz, with 2Eij = g_ij + g_ji (eq. 5.20).
  return {g[0], g[1] + g[3], g[2] + g[6],  //
          0.0,  g[4],        g[5] + g[7],  //
          0.0,  0.0,         g[8]};
}

bool is_upper_triangular(const Mat3& g) { return g[3] == 0.0 && g[6] == 0.0 && g[7] == 0.0; }

void Box::deform(const Mat3& g, double dt) {
  const double nlx = lx + dt * g[0] * lx;
  const double nxy = xy + dt * (g[0] * xy + g[1] * ly);
  const double nxz = xz + dt * (g[0] * xz + g[1] * yz + g[2] * lz);
  const double nly = ly + dt * g[4] * ly;
  const double nyz = yz + dt * (g[4] * yz + g[5] * lz);
  const double nlz = lz + dt * g[8] * lz;
  lx = nlx, xy = nxy, xz = nxz, ly = nly, yz = nyz, lz = nlz;
}

void Box::reduce_tilt() {
  if (double k = std::round(yz / ly); k != 0.0) {  // c -= k b
    yz -= k * ly;
    xz -= k * xy;
  }
  if (double k = std::round(xz / lx); k != 0.0) xz -= k * lx;  // c -= k a
  if (double k = std::round(xy / lx); k != 0.0) xy -= k * lx;  // b -= k a
}

std::array<int, 3> Box::image_of(double x, double y, double z) const {
  const int n3 = image_index(std::floor(z / lz));
  y -= n3 * yz;
  x -= n3 * xz;
  const int n2 = image_index(std::floor(y / ly));
  x -= n2 * xy;
  const int n1 = image_index(std::floor(x / lx));
  return {n1, n2, n3};
}

}  // namespace mpmx::particles
