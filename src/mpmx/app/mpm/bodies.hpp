#pragma once
// The [[body]] regions of a 2-D or 3-D deck: each shape checked on its own (finite,
// with an area, a simple polygon), the grid's sub-cell points placed in them, and the
// placement checked as a whole (every body holds points, no removal empties the deck, no
// two bodies claim one point with different velocities or laws).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"

namespace mpmx::app {

// A polygon's corners at most (its edges are checked pairwise for crossings).
inline constexpr std::size_t kMaxPolygonCorners = 1000;
// The largest coordinate or radius a body may have: products of two (areas, the edge
// crossings, a radius squared) stay finite.
inline constexpr double kMaxBodyCoordinate = 1e100;

// What is wrong with a body's shape by itself ("" when nothing): a coordinate beyond
// kMaxBodyCoordinate, a polygon of zero area, with two corners in one place or with
// edges that cross (naming both).
std::string geometry_problem(const Body& b, int dim);

// A polygon's bounding box (x, y; z 0), which Body keeps in lower and upper.
void polygon_bounds(const std::vector<std::array<double, 2>>& v, std::array<double, 3>& lo, std::array<double, 3>& hi);

// The grid's sub-cell points: per_cell per cell and axis, at the centres of equal parts
// of the cells. site(x) for each, in grid order (x fastest).
template <typename Site>
void for_each_site(const MpmConfig& c, Site&& site) {
  const int dim = c.dim;
  std::array<double, 3> l{};
  std::array<std::int64_t, 3> count{1, 1, 1};
  std::int64_t total = 1;
  for (int d = 0; d < dim; ++d) {
    l[d] = (c.upper_all[d] - c.lower_all[d]) / c.cells_all[d] / c.per_cell_all[d];
    count[d] = static_cast<std::int64_t>(c.cells_all[d]) * c.per_cell_all[d];
    total *= count[d];
  }
  for (std::int64_t k = 0; k < total; ++k) {
    std::array<double, 3> x{};
    std::int64_t r = k;
    for (int d = 0; d < dim; ++d) {
      x[d] = c.lower_all[d] + (static_cast<double>(r % count[d]) + 0.5) * l[d];
      r /= count[d];
    }
    site(x);
  }
}

// The points a deck places: every site when it has no bodies, else those in a body and
// in no removing region. keep(x, body) for each, in grid order (body -1: no bodies; else
// the first adding body that holds it).
template <typename Keep>
void place_points(const MpmConfig& c, Keep&& keep) {
  for_each_site(c, [&](const std::array<double, 3>& x) {
    int body = -1;
    for (std::size_t b = 0; b < c.bodies.size(); ++b) {
      if (!c.bodies[b].contains(x, c.dim)) continue;
      if (c.bodies[b].remove) return;
      if (body == -1) body = static_cast<int>(b);
    }
    if (!c.bodies.empty() && body < 0) return;
    keep(x, body);
  });
}

// The material points a deck places, counted without building them: deck checks and
// estimates.
std::int64_t count_points(const MpmConfig& c);

// Throws InputError naming every body that places no point (off the grid, smaller than
// the point spacing, removed whole), a removal that removes nothing, a deck whose bodies
// only remove, and two adding bodies that share points but not their velocity or law.
void check_bodies(const MpmConfig& c);

}  // namespace mpmx::app
