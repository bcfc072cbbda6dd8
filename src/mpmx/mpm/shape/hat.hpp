#pragma once
// The 1-D linear hat function of unit cell size and the pieces every 1-D scheme is
// built from (eqs. 3.9, 4.1). Coordinates are in cell units: xi = (x - lower) / dx.
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::mpm::shape {

// Hat value of a node at distance r (cell units).
inline double hat(double r) { return std::max(0.0, 1.0 - std::abs(r)); }

// Antiderivative of the hat, from -inf to r: used for the GIMP integral (eq. 3.17).
inline double hat_integral(double r) {
  if (r <= -1.0) return 0.0;
  if (r <= 0.0) return 0.5 * (1.0 + r) * (1.0 + r);
  if (r < 1.0) return 1.0 - 0.5 * (1.0 - r) * (1.0 - r);
  return 1.0;
}

// Cell holding xi and the fraction inside it; xi on the upper end belongs to the last cell.
struct CellPos {
  int cell;
  double frac;
};

inline CellPos locate(double xi, int cells) {
  int c = static_cast<int>(std::floor(xi));
  c = std::clamp(c, 0, cells - 1);
  return {c, xi - c};
}

// Beyond the end nodes the end node's shape function is continued flat (S = 1), so
// the partition of unity holds for material pushed past a driven end; a point may go
// at most one cell beyond, further stops the run with its number and position.
inline double clamp_to_grid(double xi, int cells) { return std::clamp(xi, 0.0, double(cells)); }

inline bool within_reach(double xi, int cells) { return xi >= -1.0 && xi <= cells + 1.0; }  // false for NaN
// A point more than a cell past the grid, on `axis` (0, 1, 2: x, y, z); step() adds the
// step and the time, which the scheme does not know.
class LeftGrid : public RunError {
 public:
  using RunError::RunError;
};
inline void require_inside(double xi, int cells, std::size_t p, double x, int axis = 0) {
  if (!within_reach(xi, cells)) {
    const char name = "xyz"[std::clamp(axis, 0, 2)];
    throw LeftGrid(fmt::format("particle {} left the grid ({} = {}, more than a cell past the grid's {} {} end)", p,
                               name, x, xi < 0 ? "lower" : "upper", name));
  }
}

// Hat of node i continued flat past the grid ends, integrated from -inf to xi (for the
// GIMP average, eq. 3.17), and its value.
inline double hat_ext(double xi, int i, int cells) { return hat(clamp_to_grid(xi, cells) - i); }
inline double hat_ext_integral(double xi, int i, int cells) {
  const double xc = clamp_to_grid(xi, cells);
  double v = hat_integral(xc - i);
  if (xi > cells) v += (xi - cells) * hat(cells - i);
  if (xi < 0.0) v -= (0.0 - xi) * hat(0.0 - i);
  return v;
}

// alpha of eq. 3.27 in 1-D (n_c = 2, d = 1): 0.5 (4 S_1 S_2)^{3/2}, zero on cell
// boundaries and 0.5 at the cell centre.
inline double ddmp_alpha(double frac) {
  const double q = 4.0 * frac * (1.0 - frac);
  return 0.5 * q * std::sqrt(q);
}

}  // namespace mpmx::mpm::shape
