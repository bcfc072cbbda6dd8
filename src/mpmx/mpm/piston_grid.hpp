#pragma once
// A piston carries the grid (piston.hpp): at time t the grid's corners lie n travel(t)
// from where they were at t = 0, along the piston's axis, so that its face stays on the
// grid's face nodes. Each axis follows its own piston; the face across from a piston is
// free (the deck refuses another condition there: it would move with the grid).
#include <array>

#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/grid.hpp"

namespace mpmx::mpm {

template <int Dim>
void carry_grid(Grid<Dim>& g, const Boundaries& bc, double t) {
  for (int d = 0; d < Dim; ++d) {
    double shift = 0.0;
    for (int f = 2 * d; f < 2 * d + 2; ++f)
      if (bc.face[f].type == BoundarySide::Type::piston) shift += inward(f) * bc.face[f].piston.travel(t);
    g.lower[d] = g.rest_lower[d] + shift;
    g.upper[d] = g.rest_upper[d] + shift;
  }
}

// The grid's velocity at time t, the rate of carry_grid's shift: along each axis its
// pistons' speeds along their inward normals (zero where none carries it).
template <int Dim>
std::array<double, Dim> grid_velocity(const Boundaries& bc, double t) {
  std::array<double, Dim> u{};
  for (int f = 0; f < 2 * Dim; ++f)
    if (bc.face[f].type == BoundarySide::Type::piston) u[f / 2] += inward(f) * bc.face[f].piston.speed(t);
  return u;
}

// Whether any face is a piston: the grid moves.
inline bool has_piston(const Boundaries& bc) {
  for (const BoundarySide& side : bc.face)
    if (side.type == BoundarySide::Type::piston) return true;
  return false;
}

}  // namespace mpmx::mpm
