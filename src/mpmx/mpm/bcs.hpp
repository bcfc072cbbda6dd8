#pragma once
// Boundary conditions on the end nodes of a 1-D grid: free, fixed, or a prescribed
// velocity v(t) = value + amplitude sin(omega t) (the drive of ADMPM 8.2 and 7.7).
#include <cmath>
#include <string>

namespace mpmx::mpm {

struct BoundarySide {
  enum class Type { free, fixed, velocity };
  Type type = Type::free;
  double value = 0.0;
  double amplitude = 0.0;
  double omega = 0.0;

  bool prescribed() const { return type != Type::free; }
  double velocity(double t) const {
    return type == Type::velocity ? value + amplitude * std::sin(omega * t) : 0.0;
  }
};

struct Boundaries {
  BoundarySide left, right;
};

}  // namespace mpmx::mpm
