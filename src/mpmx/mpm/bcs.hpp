#pragma once
// Boundary conditions on the faces of the grid: free, fixed, a prescribed velocity
// v(t) = value + amplitude sin(omega t) (a vector; the drive of ADMPM 8.2 and 7.7), or
// roller (normal velocity zero, tangential free: the y faces of the copper jet), or a
// piston (piston.hpp: a wall moving into the grid, which carries the grid with it).
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

  // Whether the face's own nodes take a set velocity whatever the material does.
  bool prescribed() const { return type != Type::free && type != Type::piston; }
  // Component `a` of the velocity face f holds its nodes at, at time t (fixed, roller:
  // zero; a piston: its speed along the inward normal).
  double velocity(double t, int a, int f) const {
    if (type == Type::piston) return a == f / 2 ? inward(f) * piston.speed(t) : 0.0;
    return type == Type::velocity ? value[a] + amplitude[a] * std::sin(omega * t) : 0.0;
  }
  // Whether face f holds velocity component `a` of a node on it whose own velocity at
  // time t (the material's, before the face acts) is v: a piston only while it pushes.
  bool holds(int a, int f, double v, double t) const {
    const int normal = f / 2;
    if (type == Type::piston) return a == normal && piston_contact(v, f, piston.speed(t));
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
