#include "mpmx/app/mpm/bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"

namespace mpmx::app {

namespace {

using Point = std::array<double, 2>;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// q on the segment a-b, given that the three are collinear.
bool within(const Point& a, const Point& b, const Point& q) {
  return std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= q[1] &&
         q[1] <= std::max(a[1], b[1]);
}

// Segments a-b and c-d meet (crossing, touching or overlapping).
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  return (d1 == 0 && within(c, d, a)) || (d2 == 0 && within(c, d, b)) || (d3 == 0 && within(a, b, c)) ||
         (d4 == 0 && within(a, b, d));
}

std::string edge_text(const std::vector<Point>& v, std::size_t k) {
  const Point& a = v[k];
  const Point& b = v[(k + 1) % v.size()];
  return fmt::format("{} ({}, {})-({}, {})", k + 1, a[0], a[1], b[0], b[1]);
}

std::string polygon_problem(const std::vector<Point>& v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (v[i] == v[j])
        return fmt::format("polygon corners {} and {} lie in one place ({}, {})", i + 1, j + 1, v[i][0], v[i][1]);
  // Edges that are not neighbours may not meet (a crossing's lobes may cancel the area).
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // the last edge and the first share corner 1
      if (segments_meet(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]))
        return fmt::format("polygon edges {} and {} cross: a polygon's edges may meet only at their shared corners",
                           edge_text(v, i), edge_text(v, j));
    }
  double area2 = 0.0, xlo = v[0][0], xhi = xlo, ylo = v[0][1], yhi = ylo;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = v[i];
    const Point& b = v[(i + 1) % n];
    area2 += a[0] * b[1] - b[0] * a[1];
    xlo = std::min(xlo, a[0]), xhi = std::max(xhi, a[0]), ylo = std::min(ylo, a[1]), yhi = std::max(yhi, a[1]);
  }
  // Relative to the corners' spread: collinear corners leave only rounding.
  const double span = (xhi - xlo) + (yhi - ylo);
  if (!(std::abs(area2) > 1e-12 * span * span)) return "polygon has zero area";
  for (std::size_t i = 0; i < n; ++i) {
    // Neighbouring edges share a corner; they may not fold back along one line.
    const Point& a = v[i];
    const Point& b = v[(i + 1) % n];
    const Point& c = v[(i + 2) % n];
    if (cross(a, b, c) == 0 && (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) < 0)
      return fmt::format("polygon edges {} and {} fold back over each other", edge_text(v, i),
                         edge_text(v, (i + 1) % n));
  }
  return "";
}

// The body's bounding box.
void bounds(const Body& b, int dim, std::array<double, 3>& lo, std::array<double, 3>& hi) {
  switch (b.shape) {
    case Body::Shape::box:
      lo = b.lower, hi = b.upper;
      return;
    case Body::Shape::circle:
    case Body::Shape::sphere:
      for (int d = 0; d < dim; ++d) lo[d] = b.center[d] - b.radius, hi[d] = b.center[d] + b.radius;
      return;
    case Body::Shape::polygon:
      polygon_bounds(b.vertices, lo, hi);
      return;
  }
}

bool same_motion_and_law(const Body& a, const Body& b) {
  return a.velocity == b.velocity && a.angular_velocity == b.angular_velocity && a.material == b.material;
}

}  // namespace

void polygon_bounds(const std::vector<std::array<double, 2>>& v, std::array<double, 3>& lo, std::array<double, 3>& hi) {
  lo = hi = {};
  if (v.empty()) return;
  lo = hi = {v[0][0], v[0][1], 0.0};
  for (const auto& p : v)
    for (int d = 0; d < 2; ++d) lo[d] = std::min(lo[d], p[d]), hi[d] = std::max(hi[d], p[d]);
}

bool Body::contains(const std::array<double, 3>& x, int dim) const {
  switch (shape) {
    case Shape::box:
      for (int d = 0; d < dim; ++d)
        if (x[d] < lower[d] || x[d] > upper[d]) return false;
      return true;
    case Shape::circle:
    case Shape::sphere: {
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += (x[d] - center[d]) * (x[d] - center[d]);
      return r2 <= radius * radius;
    }
    case Shape::polygon: {  // even-odd rule in the x-y plane, inside its bounding box
      if (x[0] < lower[0] || x[0] > upper[0] || x[1] < lower[1] || x[1] > upper[1]) return false;
      bool in = false;
      const std::size_t n = vertices.size();
      for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const auto& a = vertices[i];
        const auto& b = vertices[j];
        if ((a[1] > x[1]) != (b[1] > x[1]) && x[0] < (b[0] - a[0]) * (x[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
      }
      return in;
    }
  }
  return false;
}

std::string geometry_problem(const Body& b, int dim) {
  std::vector<double> coordinates;
  switch (b.shape) {
    case Body::Shape::box:
      coordinates.assign(b.lower.begin(), b.lower.begin() + dim);
      coordinates.insert(coordinates.end(), b.upper.begin(), b.upper.begin() + dim);
      break;
    case Body::Shape::circle:
    case Body::Shape::sphere:
      coordinates.assign(b.center.begin(), b.center.begin() + dim);
      coordinates.push_back(b.radius);
      break;
    case Body::Shape::polygon:
      for (const auto& p : b.vertices) coordinates.insert(coordinates.end(), p.begin(), p.end());
      break;
  }
  for (double x : coordinates)
    if (!(std::abs(x) <= kMaxBodyCoordinate))
      return fmt::format("{} is beyond {:g} in magnitude (a body's coordinates and radius must stay below it, so "
                         "that its areas and crossings are finite)",
                         x, kMaxBodyCoordinate);
  if (b.shape == Body::Shape::polygon && b.vertices.size() >= 3) return polygon_problem(b.vertices);
  return "";
}

std::int64_t count_points(const MpmConfig& c) {
  std::int64_t n = 0;
  place_points(c, [&](const std::array<double, 3>&, int) { ++n; });
  return n;
}

void check_bodies(const MpmConfig& c) {
  if (c.bodies.empty()) return;
  const std::size_t nb = c.bodies.size();
  const int dim = c.dim;
  // Over the grid's points: those each body holds, those it keeps (an adding body: the
  // first that holds the point, none removing it), those it removes from an adding body,
  // and the points two adding bodies of different motion or law both hold.
  std::vector<std::int64_t> holds(nb, 0), keeps(nb, 0), removes(nb, 0);
  std::map<std::pair<std::size_t, std::size_t>, std::int64_t> shared;
  std::int64_t kept = 0;
  std::vector<std::size_t> in;
  for_each_site(c, [&](const std::array<double, 3>& x) {
    in.clear();
    int first_add = -1, remover = -1;
    for (std::size_t b = 0; b < nb; ++b) {
      if (!c.bodies[b].contains(x, dim)) continue;
      ++holds[b];
      if (c.bodies[b].remove) {
        if (remover < 0) remover = static_cast<int>(b);
      } else {
        if (first_add < 0) first_add = static_cast<int>(b);
        for (std::size_t a : in)
          if (!same_motion_and_law(c.bodies[a], c.bodies[b])) ++shared[{a, b}];
        in.push_back(b);
      }
    }
    if (first_add < 0) return;
    if (remover >= 0) ++removes[static_cast<std::size_t>(remover)];
    else ++keeps[static_cast<std::size_t>(first_add)], ++kept;
  });

  auto spacing = [&] {
    double h = std::numeric_limits<double>::infinity();
    for (int d = 0; d < dim; ++d) h = std::min(h, (c.upper_all[d] - c.lower_all[d]) / c.cells_all[d] / c.per_cell_all[d]);
    return h;
  };
  std::vector<std::string> errors;
  const std::string where = c.deck_path.empty() ? "deck" : c.deck_path;
  auto say = [&](std::size_t b, const std::string& what) {
    errors.push_back(fmt::format("{}: [[body]] {}: {}", where, b, what));  // from 0, as run.json numbers them
  };
  const bool any_adds = std::any_of(c.bodies.begin(), c.bodies.end(), [](const Body& b) { return !b.remove; });
  for (std::size_t b = 0; b < nb; ++b) {
    const Body& body = c.bodies[b];
    if (body.remove) {
      if (!any_adds)
        say(b, "removes points, but no body adds any (a deck without [[body]] fills the grid; to cut a hole, give "
               "the solid as a body too)");
      else if (removes[b] == 0)
        say(b, holds[b] == 0 ? "removes no point: it holds no point of the grid"
                             : "removes no point: it overlaps no adding body");
      continue;
    }
    if (holds[b] == 0) {
      std::array<double, 3> lo{}, hi{};
      bounds(body, dim, lo, hi);
      bool off = false;
      for (int d = 0; d < dim; ++d) off = off || hi[d] < c.lower_all[d] || lo[d] > c.upper_all[d];
      say(b, off ? "holds no point: it lies wholly off the grid"
                 : fmt::format("holds no point: it lies between the grid's points (spaced {:g}; make it larger or "
                               "raise particles.per_cell)",
                               spacing()));
    } else if (keeps[b] == 0) {
      say(b, fmt::format("places no point: each of the {} points it holds is removed or belongs to an earlier body",
                         holds[b]));
    }
  }
  for (const auto& [pair, n] : shared)
    errors.push_back(fmt::format(
        "{}: [[body]] {} and [[body]] {} overlap ({} points lie in both) with different velocities or materials: "
        "the points would take [[body]] {}'s; make the bodies disjoint",
        where, pair.first, pair.second, n, pair.first));
  if (errors.empty() && kept == 0) errors.push_back(fmt::format("{}: the bodies place no material point", where));
  if (errors.empty()) return;
  std::string all;
  for (const auto& e : errors) all += (all.empty() ? "" : "\n") + e;
  throw InputError(all);
}

}  // namespace mpmx::app
