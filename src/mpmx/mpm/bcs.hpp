#pragma once
// Boundary conditions on the faces of the grid: free, fixed, a prescribed velocity
// v(t) = value + amplitude sin(omega t) (a vector; the drive of ADMPM 8.2 and 7.7), or
// roller (normal velocity zero, tangential free: the y faces of the copper jet), or a
// piston (piston.hpp: a wall moving into the grid, holding the nodes behind it).
#include <array>
#include <cmath>
#include <string>

#include "mpmx/mpm/piston.hpp"

namespace mpmx::mpm {

struct BoundarySide {
  enum class Type { free, fixed, velocity, roller, piston };
  Type type = Type::free;
  std::array<double, 3> value{};
  std::array<double, 3> amplitude{};
  double omega = 0.0;
  Piston piston;

  // Whether the face's own nodes take a set velocity (a piston's nodes follow its face).
  bool prescribed() const { return type != Type::free && type != Type::piston; }
  // Component `a` of the prescribed velocity (fixed: zero).
  double velocity(double t, int a = 0) const {
    return type == Type::velocity ? value[a] + amplitude[a] * std::sin(omega * t) : 0.0;
  }
  // Whether this face holds velocity component `a` of its nodes; `normal` is the face's axis.
  bool holds(int a, int normal) const {
    return type == Type::fixed || type == Type::velocity || (type == Type::roller && a == normal);
  }
};

// Faces in the order x lower, x upper, y lower, y upper, z lower, z upper. In 1-D the
// deck calls the x faces left and right.
struct Boundaries {
  std::array<BoundarySide, 6> face;
  BoundarySide& left() { return face[0]; }
  BoundarySide& right() { return face[1]; }
  const BoundarySide& left() const { return face[0]; }
  const BoundarySide& right() const { return face[1]; }
};

inline const char* face_name(int f) {
  static const char* names[] = {"x_lower", "x_upper", "y_lower", "y_upper", "z_lower", "z_upper"};
  return names[f];
}

}  // namespace mpmx::mpm
