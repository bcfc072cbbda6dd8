#include "mpmx/app/mpm/describe.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpmx/core/file_text.hpp"
#include "mpmx/mpm/bcs.hpp"

namespace mpmx::app {

std::vector<std::string> describe_pistons_and_gauges(const MpmConfig& c) {
  std::vector<std::string> lines;
  for (int f = 0; f < 2 * c.dim; ++f) {
    const auto& side = c.boundary.face[f];
    if (side.type != mpm::BoundarySide::Type::piston) continue;
    const std::string face = c.dim == 1 ? (f == 0 ? "left" : "right") : mpm::face_name(f);
    const auto& p = side.piston;
    const std::string speed =
        p.speeds.size() == 1
            ? fmt::format("at {:.6g} into the grid", p.speeds.front())
            : fmt::format("by a table of {} speeds from t = {:.6g} to {:.6g} ({:.6g} to {:.6g}, straight lines between)",
                          p.speeds.size(), p.times.front(), p.times.back(),
                          *std::min_element(p.speeds.begin(), p.speeds.end()),
                          *std::max_element(p.speeds.begin(), p.speeds.end()));
    lines.push_back(fmt::format("piston on {}: moves {}; its face is {:.6g} in at time.end", face, speed,
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
