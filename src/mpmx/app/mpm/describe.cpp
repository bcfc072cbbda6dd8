#include "mpmx/app/mpm/describe.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpmx/core/file_text.hpp"
#include "mpmx/mpm/bcs.hpp"

namespace mpmx::app {

namespace {

// Whether the deck's material reaches face f, to within a cell: the whole grid where the
// deck has no bodies, else a body (not one that cuts material away) that comes so near.
bool material_at(const MpmConfig& c, int f) {
  if (c.bodies.empty()) return true;
  const int a = f / 2;
  const double cell = (c.upper_all[a] - c.lower_all[a]) / c.cells_all[a];
  for (const Body& b : c.bodies) {
    if (b.remove) continue;
    const bool round = b.shape == Body::Shape::circle || b.shape == Body::Shape::sphere;
    const double lo = round ? b.center[a] - b.radius : b.lower[a], hi = round ? b.center[a] + b.radius : b.upper[a];
    if (f % 2 == 0 ? lo <= c.lower_all[a] + cell : hi >= c.upper_all[a] - cell) return true;
  }
  return false;
}

}  // namespace

std::vector<std::string> describe_pistons_and_gauges(const MpmConfig& c) {
  std::vector<std::string> lines;
  for (int f = 0; f < 2 * c.dim; ++f) {
    const auto& side = c.boundary.face[f];
    const std::string face = c.dim == 1 ? (f == 0 ? "left" : "right") : mpm::face_name(f);
    // A velocity face whose steady part pushes into the material holds only the face's
    // own nodes, which the material leaves: the drive fades (docs/guide.md, Piston).
    const double push = mpm::inward(f) * side.value[f / 2];
    if (side.type == mpm::BoundarySide::Type::velocity && push > 0.0 && material_at(c, f))
      lines.push_back(fmt::format(
          "note: boundary.{} is a velocity face pushing into the material at {:.6g}: it holds the face's own "
          "nodes, which the material leaves, so the drive stops acting; a drive is type = \"piston\", a wall "
          "that moves with the material's face",
          face, push));
    if (side.type != mpm::BoundarySide::Type::piston) continue;
    const auto& p = side.piston;
    const std::string speed =
        p.speeds.size() == 1
            ? fmt::format("at {:.6g} into the grid", p.speeds.front())
            : fmt::format("by a table of {} speeds from t = {:.6g} to {:.6g} ({:.6g} to {:.6g}, straight lines between)",
                          p.speeds.size(), p.times.front(), p.times.back(),
                          *std::min_element(p.speeds.begin(), p.speeds.end()),
                          *std::max_element(p.speeds.begin(), p.speeds.end()));
    lines.push_back(fmt::format("piston on {}: moves {}; its face is {:.6g} in at time.end, the grid carried with it",
                                face, speed,
                                p.travel(c.end)));
  }
  for (const auto& g : c.gauges) {
    std::string what;
    if (g.kind == GaugeConfig::Kind::point) {
      std::vector<double> at(g.at.begin(), g.at.begin() + c.dim);
      what = fmt::format("the material point nearest [{}]: place, velocity, stress, density", fmt::join(at, ", "));
    } else {
      const std::string face = g.face < 2 && c.dim == 1 ? (g.face == 0 ? "left" : "right") : mpm::face_name(g.face);
      what = fmt::format("free-surface velocity: the mean of the outermost points of {}'s {} face",
                         g.body >= 0 ? escape_controls(c.bodies[g.body].name) : std::string("the material"), face);
    }
    lines.push_back(fmt::format("gauge {}: {}, every {} step{} -> gauge_{}.csv", g.name, what, g.every,
                                g.every == 1 ? "" : "s", g.name));
  }
  return lines;
}

}  // namespace mpmx::app
