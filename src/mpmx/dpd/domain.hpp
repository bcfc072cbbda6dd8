#pragma once
// The DPD domain: an orthogonal box [0,lx)x[0,ly)x[0,lz) whose axes are each periodic
// or open (free surfaces, as the seed's non-periodic nanorods, sec. 4.1). Along an open
// axis the box only names a volume (pressure) and the dump's bounds; particles may
// leave it.
#include <array>
#include <cmath>

#include "mpmx/particles/box.hpp"

namespace mpmx::dpd {

struct Domain {
  particles::Box box;                                     // orthogonal: xy = xz = yz = 0
  std::array<bool, 3> periodic{true, true, true};

  double length(int d) const { return d == 0 ? box.lx : d == 1 ? box.ly : box.lz; }
  double volume() const { return box.volume(); }
  // Brings a coordinate along a periodic axis into [0, L).
  double wrap(int d, double x) const {
    if (!periodic[d]) return x;
    const double l = length(d);
    double w = x - std::floor(x / l) * l;
    if (w >= l) w -= l;  // x just below 0 rounds up to l
    return w;
  }
};

}  // namespace mpmx::dpd
