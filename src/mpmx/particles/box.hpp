#pragma once
// The periodic box: a rectangular fundamental box [0,lx)x[0,ly)x[0,lz) whose images
// slide (figs. 5.2-5.3). The image lattice is spanned by a = (lx,0,0), b = (xy,ly,0),
// c = (xz,yz,lz): the columns of the upper-triangular h, deformed by dh/dt = G h with
// an upper-triangular velocity gradient G (eqs. 5.7, 5.9, 5.20).
#include <algorithm>
#include <array>
#include <cmath>

namespace mpmx::particles {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major: m[3*row + col]

// Eq. 5.20: adds the rotation that makes a velocity gradient upper triangular,
// G' = [[exx, 2exy, 2exz], [0, eyy, 2eyz], [0, 0, ezz]].
Mat3 upper_triangular(const Mat3& velocity_gradient);
bool is_upper_triangular(const Mat3& g);

struct Box {
  double lx = 1, ly = 1, lz = 1;  // edge lengths of the fundamental box (Angstrom)
  double xy = 0, xz = 0, yz = 0;  // slide of the images (tilt of the lattice vectors)

  double volume() const { return lx * ly * lz; }
  // Translation to the image with integer indices (n1, n2, n3).
  Vec3 shift(int n1, int n2, int n3) const {
    return {n1 * lx + n2 * xy + n3 * xz, n2 * ly + n3 * yz, n3 * lz};
  }
  // One leapfrog step of the box under upper-triangular G: h <- (I + G dt) h (eq. 5.7).
  void deform(const Mat3& g, double dt);
  // Lattice reduction (b -= k a, c -= k b, c -= k a) so |xy| <= lx/2, |xz| <= lx/2,
  // |yz| <= ly/2; the periodic system is unchanged.
  void reduce_tilt();
  // Image indices that bring p into the fundamental box: p - shift(n) is inside (eq. 5.8
  // and the unique-image argument of eqs. 5.12-5.17).
  std::array<int, 3> image_of(double x, double y, double z) const;
};

// A floored or ceiled ratio as an image index: 0 where it is not finite (a box or an atom
// gone non-finite, which the run stops on at its next check), bounded otherwise, so that
// the cast to int is always defined.
inline int image_index(double v) { return std::isfinite(v) ? static_cast<int>(std::clamp(v, -1e9, 1e9)) : 0; }

}  // namespace mpmx::particles
