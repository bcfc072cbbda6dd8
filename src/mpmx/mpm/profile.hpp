#pragma once
// Initial-state profiles along x: uniform, sinusoid, step, and a step smoothed by
// tanh over a given number of cells (dissertation sec. 6.3: 26 cells, 13 each side).
// In 2-D and 3-D a profile runs along its unit `normal` (x by default): it is evaluated
// at n . x, and a velocity profile points along n.
#include <array>
#include <cmath>
#include <numbers>

namespace mpmx::mpm {

struct Profile {
  enum class Kind { uniform, sinusoid, step, tanh };
  Kind kind = Kind::uniform;
  double value = 0.0;      // uniform; also the offset of a sinusoid
  double amplitude = 0.0;  // sinusoid: value + amplitude sin(mode pi (x - lower) / length)
  double mode = 1.0;
  double left = 0.0, right = 0.0, at = 0.0;  // step and tanh
  double cells = 0.0;                        // tanh: width of the transition in cells
  std::array<double, 3> normal{1.0, 0.0, 0.0};  // 2-D, 3-D: the direction the profile runs along

  // The coordinate the profile reads at point x of a `dim`-dimensional deck.
  double along(const std::array<double, 3>& x, int dim) const {
    double s = 0.0;
    for (int d = 0; d < dim; ++d) s += normal[d] * x[d];
    return s;
  }

  // `lower`, `length` of the domain and the cell size `dx` fix the sinusoid and tanh.
  double operator()(double x, double lower, double length, double dx) const {
    switch (kind) {
      case Kind::uniform: return value;
      case Kind::sinusoid:
        return value + amplitude * std::sin(mode * std::numbers::pi * (x - lower) / length);
      case Kind::step: return x < at ? left : right;
      case Kind::tanh: {
        // The transition spans `cells` cells: tanh reaches +-0.96 at +-cells/2.
        const double w = 0.25 * cells * dx;
        return right + 0.5 * (left - right) * (1.0 - std::tanh((x - at) / w));
      }
    }
    return value;
  }
};

}  // namespace mpmx::mpm
