#include "mpmx/app/mpm/deck.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpmx/app/case_table.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/app/mpm/bodies.hpp"
#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/signal_speed.hpp"
#include "mpmx/app/mpm/unit_slips.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/lammps_dump.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

using io::Deck;
using io::Section;
using mpm::BoundarySide;
using mpm::Profile;

constexpr std::size_t kMaxGaugeName = 100;  // gauge_<name>.csv stays well inside a file name's 255 bytes

// The laws' work left until every key is read (material::Context::later), with the table
// each was read from.
using LaterWork = std::vector<std::pair<Section, std::function<void(Table&)>>>;

// The reader's context for the law of `table`, its later work kept in `later`.
material::Context law_context(const Section& table, const MpmConfig& c, const std::string& deck_dir,
                              LaterWork& later) {
  material::Context ctx = material_context(c.dim, deck_dir, c.units);
  ctx.later = [&later, table](std::function<void(Table&)> work) { later.emplace_back(table, std::move(work)); };
  return ctx;
}

// A step or tanh front must lie on the grid, along the profile's normal (outside it the
// profile is a uniform state, surely not what the deck meant).
Profile read_profile(Section s, double fallback, const MpmConfig& c) {
  const int dim = c.dim;
  Profile p;
  p.value = fallback;
  if (!s.present()) return p;
  const std::string kind = s.choice("profile", {"uniform", "sinusoid", "step", "tanh"}, "uniform");
  if (kind == "uniform") {
    p.kind = Profile::Kind::uniform;
    p.value = s.number("value", fallback);
  } else if (kind == "sinusoid") {
    p.kind = Profile::Kind::sinusoid;
    p.value = s.number("offset", 0.0);
    p.amplitude = s.number("amplitude");
    p.mode = s.number("mode", 1.0);
    s.check(p.mode >= 1.0 && p.mode <= 1e6 && p.mode == std::floor(p.mode), "mode",
            "must be a whole number from 1 to 1000000 (half-waves along the grid)");
  } else {
    p.kind = kind == "step" ? Profile::Kind::step : Profile::Kind::tanh;
    p.left = s.number("left");
    p.right = s.number("right");
    p.at = s.number("at");
    if (kind == "tanh") {
      p.cells = s.number("cells");
      s.positive("cells", p.cells);
    }
  }
  if (s.has("normal")) {
    const auto n = s.numbers("normal");
    double len = 0.0;
    for (double v : n) len += v * v;
    len = std::sqrt(len);
    if (dim == 1 || static_cast<int>(n.size()) != dim || !(len > 0.0) || !std::isfinite(len)) {
      s.check(false, "normal", fmt::format("needs {} numbers, not all zero, in a 2-D or 3-D deck", dim));
    } else {
      p.normal = {0.0, 0.0, 0.0};
      for (int d = 0; d < dim; ++d) p.normal[d] = n[d] / len;
    }
  }
  if ((kind == "step" || kind == "tanh") && std::isfinite(p.at)) {
    double lo = 0.0, hi = 0.0;  // n . x over the grid's box
    for (int d = 0; d < dim; ++d) {
      const double a = p.normal[d] * c.lower_all[d], b = p.normal[d] * c.upper_all[d];
      lo += std::min(a, b), hi += std::max(a, b);
    }
    if (lo < hi)
      s.check(p.at >= lo && p.at <= hi, "at",
              fmt::format("must lie on the grid, from {} to {} (outside it the {} is a uniform state)", lo, hi, kind));
  }
  return p;
}

// A piston's speed into the grid (piston.hpp): `velocity` a number, or with `times` one
// speed per time, the times increasing from t >= 0.
Piston read_piston(Section& s) {
  Piston p;
  if (!s.has("times")) {
    p.speeds = {s.number("velocity")};
    return p;
  }
  const auto t = s.numbers("times");
  const auto v = s.numbers("velocity");
  s.check(!t.empty() && t.size() == v.size(), "velocity",
          fmt::format("needs one speed per entry of times ({} times, {} speeds)", t.size(), v.size()));
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (k == 0) s.check(t[0] >= 0.0, "times", fmt::format("starts at t = {}: a piston's history starts at t >= 0", t[0]));
    else if (!(t[k] > t[k - 1]))
      s.check(false, "times",
              fmt::format("must increase: times[{}] = {} does not follow times[{}] = {}", k, t[k], k - 1, t[k - 1]));
  }
  if (t.empty() || t.size() != v.size()) return p;
  p.times = t;
  p.speeds = v;
  return p;
}

// A face's condition: free, fixed, roller (normal velocity zero), a velocity
// value + amplitude sin(omega t) (a number in 1-D and a vector in 2-D/3-D) or a piston.
// `length`: the grid's extent along the face's axis; `end`: time.end.
BoundarySide read_side(Section s, int dim, double length, double end) {
  BoundarySide b;
  if (!s.present()) return b;
  const std::string type = s.choice("type", {"free", "fixed", "velocity", "roller", "piston"}, "free");
  b.type = type == "free"     ? BoundarySide::Type::free
           : type == "fixed"  ? BoundarySide::Type::fixed
           : type == "roller" ? BoundarySide::Type::roller
           : type == "piston" ? BoundarySide::Type::piston
                              : BoundarySide::Type::velocity;
  if (b.type == BoundarySide::Type::piston) {
    b.piston = read_piston(s);
    double most = 0.0;  // the farthest the face gets: at a time of the table or at the end
    for (double t : b.piston.times) most = std::max(most, b.piston.travel(std::min(std::max(t, 0.0), end)));
    most = std::max(most, b.piston.travel(end));
    s.check(!(most >= length), "velocity",
            fmt::format("moves the piston {:.6g} into the grid by time.end = {}: past its far side, {:.6g} away", most,
                        end, length));
  }
  if (type == "roller" && dim == 1)
    s.check(false, "type", "a roller holds the normal velocity only: in 1-D use fixed");
  if (b.type == BoundarySide::Type::velocity) {
    if (dim == 1) {
      b.value[0] = s.number("value", 0.0);
      b.amplitude[0] = s.number("amplitude", 0.0);
    } else {
      const auto v = s.numbers("value", std::vector<double>(dim, 0.0));
      const auto a = s.numbers("amplitude", std::vector<double>(dim, 0.0));
      s.check(static_cast<int>(v.size()) == dim, "value", fmt::format("needs {} components", dim));
      s.check(static_cast<int>(a.size()) == dim, "amplitude", fmt::format("needs {} components", dim));
      for (int d = 0; d < dim && d < static_cast<int>(v.size()); ++d) b.value[d] = v[d];
      for (int d = 0; d < dim && d < static_cast<int>(a.size()); ++d) b.amplitude[d] = a[d];
    }
    b.omega = s.number("omega", 0.0);
  }
  return b;
}

// A vector of `dim` numbers (a number is taken for every axis where `broadcast`).
std::array<double, 3> read_vector(Section& s, std::string_view key, int dim, std::array<double, 3> fallback,
                                  bool required) {
  std::array<double, 3> r = fallback;
  if (!s.has(key)) {
    if (required) s.number(key);  // records the missing key
    return r;
  }
  const auto v = s.numbers(key);
  if (static_cast<int>(v.size()) != dim) {
    s.check(false, key, fmt::format("needs {} numbers (grid.dim = {})", dim, dim));
    return r;
  }
  for (int d = 0; d < dim; ++d) r[d] = v[d];
  return r;
}

// `index`: the body's place among the deck's [[body]] tables, from 0 (as run.json and the
// points' `body` field number it).
Body read_body(Section s, const MpmConfig& c, const std::string& deck_dir, LaterWork& later, std::size_t index) {
  const int dim = c.dim;
  Body b;
  const std::vector<std::string> shapes =
      dim == 2 ? std::vector<std::string>{"box", "circle", "polygon"} : std::vector<std::string>{"box", "sphere"};
  const std::string shape = s.choice("shape", shapes);
  b.shape = shape == "box" ? Body::Shape::box : shape == "circle" ? Body::Shape::circle
            : shape == "sphere" ? Body::Shape::sphere : Body::Shape::polygon;
  b.remove = s.boolean("remove", false);
  b.name = s.string("name", "");
  if (b.shape == Body::Shape::box) {
    b.lower = read_vector(s, "lower", dim, {}, true);
    b.upper = read_vector(s, "upper", dim, {}, true);
    for (int d = 0; d < dim; ++d)
      s.check(b.upper[d] > b.lower[d], "upper", "must exceed lower on every axis");
  } else if (b.shape == Body::Shape::polygon) {
    const auto v = s.numbers("vertices");
    const bool pairs = v.size() >= 6 && v.size() % 2 == 0 && v.size() <= 2 * kMaxPolygonCorners;
    s.check(pairs, "vertices",
            fmt::format("needs x, y pairs of 3 to {} corners: [x0, y0, x1, y1, ...]", kMaxPolygonCorners));
    for (std::size_t k = 0; pairs && k + 1 < v.size(); k += 2) b.vertices.push_back({v[k], v[k + 1]});
    polygon_bounds(b.vertices, b.lower, b.upper);
  } else {
    b.center = read_vector(s, "center", dim, {}, true);
    b.radius = s.number("radius");
    s.positive("radius", b.radius);
  }
  if (const std::string why = geometry_problem(b, dim); !why.empty())
    s.check(false, b.shape == Body::Shape::polygon ? "vertices" : b.shape == Body::Shape::box ? "upper" : "radius",
            fmt::format("[[body]] {}: {}", index, why));
  if (!b.remove) b.velocity = read_vector(s, "velocity", dim, {}, false);
  else if (s.has("velocity")) s.check(false, "velocity", "a region that removes points has no velocity");
  if (s.has("angular_velocity")) {
    s.check(dim == 2 && b.shape == Body::Shape::circle && !b.remove, "angular_velocity",
            "a rigid spin is given to a circle of a 2-D deck");
    b.angular_velocity = s.number("angular_velocity");
  }
  if (s.has("material")) {  // its own law; otherwise the deck's [material]
    s.check(!b.remove, "material", "a region that removes points has no material");
    Section m = s.table("material");
    if (!b.remove) b.material = read_material(m, law_context(m, c, deck_dir, later));
  }
  return b;
}

// [case]: the id, title, seed section and units.
void read_case(Section& root, MpmConfig& c) {
  const CaseTable cs = read_case_table(root, c.deck_path, true, "");
  c.id = cs.id;  // printed on progress and result lines
  c.title = cs.title;
  c.seed = cs.seed;
  c.units = cs.units;
}

// [grid]: 1-D lower, upper, cells; 2-D and 3-D an array each.
void read_grid(Section& root, MpmConfig& c) {
  Section g = root.table("grid");
  c.dim = g.integer_int("dim", 1, 1, 3);
  const int dim = c.dim;
  if (dim == 1) {
    c.lower = g.number("lower", 0.0);
    c.upper = g.number("upper");
    g.check(c.upper > c.lower, "upper", fmt::format("must exceed grid.lower = {}", c.lower));
    g.check(std::isfinite(c.upper - c.lower), "upper", "grid.upper - grid.lower overflows: the grid's length must be finite");
    c.cells = g.integer_int("cells", 1, 10'000'000);
    c.lower_all[0] = c.lower, c.upper_all[0] = c.upper, c.cells_all[0] = c.cells;
  } else {
    c.lower_all = read_vector(g, "lower", dim, {}, true);
    c.upper_all = read_vector(g, "upper", dim, {1.0, 1.0, 1.0}, true);
    for (int d = 0; d < dim; ++d) {
      g.check(c.upper_all[d] > c.lower_all[d], "upper", "must exceed grid.lower on every axis");
      g.check(std::isfinite(c.upper_all[d] - c.lower_all[d]), "upper",
              "upper - lower overflows: the grid's edges must be finite");
    }
    const auto n = g.integers("cells", 1, 100'000);
    g.check(static_cast<int>(n.size()) == dim, "cells", fmt::format("needs {} integers (grid.dim = {})", dim, dim));
    for (int d = 0; d < dim && d < static_cast<int>(n.size()); ++d) c.cells_all[d] = static_cast<int>(n[d]);
    c.lower = c.lower_all[0], c.upper = c.upper_all[0], c.cells = c.cells_all[0];
  }
}

// [particles]: per cell along each axis, and whether they move (every key has a default:
// the table may be left out).
void read_particles(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  Section pt = root.optional_table("particles");
  if (dim == 1 || !pt.has("per_cell") || pt.value_text("per_cell").find('[') == std::string::npos) {
    const int n = pt.integer_int("per_cell", 2, 1, 1'000'000);
    c.per_cell_all = {n, dim > 1 ? n : 1, dim > 2 ? n : 1};
  } else {
    const auto n = pt.integers("per_cell", 1, 1000);
    pt.check(static_cast<int>(n.size()) == dim, "per_cell", fmt::format("needs {} integers (grid.dim = {})", dim, dim));
    for (int d = 0; d < dim && d < static_cast<int>(n.size()); ++d) c.per_cell_all[d] = static_cast<int>(n[d]);
  }
  c.per_cell = c.per_cell_all[0];
  c.move = pt.boolean("move", true);
}

// [[body]] regions (2-D, 3-D).
void read_bodies(Section& root, MpmConfig& c, const std::string& deck_dir, LaterWork& later) {
  const int dim = c.dim;
  if (dim > 1)
    for (auto& b : root.tables("body")) {
      c.bodies.push_back(read_body(b, c, deck_dir, later, c.bodies.size()));
      const std::string& name = c.bodies.back().name;  // what a gauge calls it: one body's
      for (std::size_t k = 0; !name.empty() && k + 1 < c.bodies.size(); ++k)
        if (c.bodies[k].name == name)
          b.check(false, "name", fmt::format("[[body]] {} is called {} too", k, escape_controls(name)));
    }
  else if (root.has("body"))
    root.check(false, "body", "1-D decks fill the grid; [[body]] regions are for 2-D and 3-D");
}

// [scheme]: the shape scheme, its sub-points, the velocity update, DDMP's alpha.
void read_scheme(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  Section sc = root.table("scheme");
  const std::string name = sc.choice("name", mpm::scheme_names());
  c.scheme.scheme = mpm::scheme_from_name(name);
  if (c.scheme.scheme == mpm::Scheme::ddmp_subpoints) {
    if (dim == 1 || sc.value_text("subpoints").find('[') == std::string::npos) {
      c.scheme.subpoints = sc.integer_int("subpoints", 1, dim == 1 ? 4096 : dim == 2 ? 16 : 8);
      c.scheme.subpoints_axes = {c.scheme.subpoints, dim > 1 ? c.scheme.subpoints : 1, dim > 2 ? c.scheme.subpoints : 1};
    } else {
      const auto n = sc.integers("subpoints", 1, 64);
      sc.check(static_cast<int>(n.size()) == dim, "subpoints", fmt::format("needs {} integers (grid.dim = {})", dim, dim));
      std::int64_t all = 1;
      for (int d = 0; d < dim && d < static_cast<int>(n.size()); ++d) c.scheme.subpoints_axes[d] = static_cast<int>(n[d]), all *= n[d];
      sc.check(all <= 4096, "subpoints", "at most 4096 sub-points per particle");
      c.scheme.subpoints = c.scheme.subpoints_axes[0];
    }
  } else if (sc.has("subpoints")) {
    sc.check(false, "subpoints", fmt::format("only ddmp_subpoints uses sub-points, not {}", name));
  }
  // MUSL by default: the midpoint form amplifies (determinant > 1, docs/theory.md) and "updated"
  // loses energy at contacts (N3: -7.9% against MUSL's -0.8%).
  const std::string update = sc.choice("update_velocity", {"midpoint", "updated", "musl"}, "musl");
  c.scheme.midpoint_gradient = update == "midpoint";
  c.scheme.musl = update == "musl";
  if (mpm::scheme_info(c.scheme.scheme).ddmp && dim > 1)
    c.scheme.alpha = sc.choice("alpha", {"eq_7_3", "axis_product"}, "eq_7_3") == "eq_7_3" ? mpm::DdmpAlpha::eq_7_3
                                                                                     : mpm::DdmpAlpha::axis_product;
  else if (sc.has("alpha"))
    sc.check(false, "alpha", "only ddmp and ddmp_subpoints in 2-D and 3-D choose their alpha");
}

// [material], and each body's own: one kind (solid or gas) for the whole deck.
void read_materials(Section& root, MpmConfig& c, const std::string& deck_dir, LaterWork& later) {
  // [material] is every point's law unless its body names its own; it may be left out
  // when every body does.
  const bool bodies_own = !c.bodies.empty() && std::all_of(c.bodies.begin(), c.bodies.end(), [](const Body& b) {
    return b.remove || b.material;
  });
  auto& mat = c.material;
  if (bodies_own && !root.has("material")) {
    for (const auto& b : c.bodies)
      if (b.material) {
        mat.spec = b.material;
        break;
      }
  } else {
    Section m = root.table("material");
    mat.small_strain = m.boolean("small_strain", false);
    mat.spec = read_material(m, law_context(m, c, deck_dir, later));
  }
  for (const auto& b : c.bodies) {
    if (!b.material || !mat.spec) continue;
    if (b.material->solid() != mat.spec->solid())
      root.check(false, "body", "solids and gases in one deck are not supported: every body's material.model must be "
                                "of the same kind as the others");
    if (!b.material->per_body())
      root.check(false, "body",
                 fmt::format("{} is the deck's [material] only: a body does not take it", b.material->name()));
  }
  if (mat.spec) mat.model = mat.spec->name();
}

// The figures of the deck's [material] the references and messages read, once its law is
// complete (after the reading's later work).
void material_figures(MpmConfig& c) {
  auto& mat = c.material;
  if (mat.spec) {
    mat.density = mat.spec->density();
    mat.density_unstrained = mat.spec->density_of_unstrained();
    if (const double m = mat.spec->uniaxial_modulus(); m > 0) mat.youngs_modulus = m;
    if (const auto gas = mat.spec->gas_law()) mat.sound_speed = gas->c, mat.gamma = gas->gamma;
  }
}

// [initial]: velocity always; strain (solids) or pressure (gases).
void read_initial(Section& in, MpmConfig& c) {
  const auto& mat = c.material;
  c.velocity = read_profile(in.optional_table("velocity"), 0.0, c);
  const bool solid = mat.solid();
  if (solid) {
    c.strain = read_profile(in.optional_table("strain"), 0.0, c);
    if (in.has("pressure")) in.check(false, "pressure", "a solid takes [initial.strain], not pressure");
  } else {
    const auto gas = mat.spec ? mat.spec->gas_law() : std::nullopt;
    const double p_default = gas && gas->isothermal ? gas->c * gas->c * gas->rho : 1.0;
    c.pressure = read_profile(in.optional_table("pressure"), p_default, c);
    if (in.has("strain")) in.check(false, "strain", "a gas takes [initial.pressure], not strain");
  }
}

// [boundary]: each face's condition.
void read_boundary(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  Section b = root.optional_table("boundary");
  if (dim == 1) {
    c.boundary.left() = read_side(b.optional_table("left"), 1, c.upper - c.lower, c.end);
    c.boundary.right() = read_side(b.optional_table("right"), 1, c.upper - c.lower, c.end);
  } else {
    for (int f = 0; f < 2 * dim; ++f)
      c.boundary.face[f] = read_side(b.optional_table(mpm::face_name(f)), dim,
                                     c.upper_all[f / 2] - c.lower_all[f / 2], c.end);
  }
  // A piston carries the grid along its axis (mpm/piston_grid.hpp): the face across from
  // it moves with the grid, so it holds nothing.
  auto name = [&](int f) { return std::string(dim == 1 ? (f == 0 ? "left" : "right") : mpm::face_name(f)); };
  for (int f = 0; f < 2 * dim; ++f) {
    if (c.boundary.face[f].type != BoundarySide::Type::piston || c.boundary.face[f ^ 1].type == BoundarySide::Type::free)
      continue;
    b.optional_table(name(f ^ 1))
        .check(false, "type",
               fmt::format("must be free across from the piston on {}: the piston carries the grid with it, and this "
                           "face with it. A piston against a held face is the wall problem seen from the piston: "
                           "the piston's face fixed, the material sent at minus its speed ([initial] velocity), this "
                           "face a velocity face at minus its speed",
                           name(f)));
  }
}

// [[gauge]]: a point's history (`at`, inside the material) or a body face's free-surface
// velocity (`type = "free_surface"`, `body` by its name, `face`).
void read_gauges(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  std::vector<std::string> faces = {"left", "right"};  // the x faces, as 1-D decks call them
  for (int f = 0; f < 2 * dim; ++f) faces.push_back(mpm::face_name(f));
  for (auto& s : root.tables("gauge")) {
    GaugeConfig g;
    g.name = s.string("name", fmt::format("{}", c.gauges.size() + 1));
    const bool plain = !g.name.empty() && std::all_of(g.name.begin(), g.name.end(), [](char ch) {
      return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
    });
    s.check(plain, "name", "names the file gauge_<name>.csv: letters, digits, _ and - only");
    // A file name of more than 255 bytes is refused by the file system only when the run
    // first writes it.
    s.check(g.name.size() <= kMaxGaugeName, "name",
            fmt::format("is {} characters long: at most {} (it names the file gauge_<name>.csv)", g.name.size(),
                        kMaxGaugeName));
    for (const auto& other : c.gauges)
      if (other.name == g.name)
        s.check(false, "name", fmt::format("another [[gauge]] is called {}", escape_controls(g.name)));
    g.every = s.integer("every", 1, 1, std::numeric_limits<std::int64_t>::max());
    g.kind = s.choice("type", {"point", "free_surface"}, "point") == "point" ? GaugeConfig::Kind::point
                                                                             : GaugeConfig::Kind::free_surface;
    if (g.kind == GaugeConfig::Kind::point) {
      if (dim == 1) g.at[0] = s.number("at");
      else g.at = read_vector(s, "at", dim, {}, true);
      // It follows the point nearest `at`: `at` must lie in the material, not beside it.
      bool inside = true;
      for (int d = 0; d < dim; ++d) inside = inside && g.at[d] >= c.lower_all[d] && g.at[d] <= c.upper_all[d];
      if (inside && !c.bodies.empty()) {
        bool added = false, removed = false;
        for (const auto& b : c.bodies) {
          if (!b.contains(g.at, dim)) continue;
          (b.remove ? removed : added) = true;
        }
        inside = added && !removed;
      }
      if (!inside) {
        std::vector<double> at(g.at.begin(), g.at.begin() + dim);
        s.check(false, "at",
                fmt::format("[{}] lies outside the material ({}): a gauge follows the material point nearest it",
                            fmt::join(at, ", "), c.bodies.empty() ? "the grid" : "every [[body]]"));
      }
    } else {
      const std::string face = s.choice("face", faces);
      g.face = face == "left" ? 0 : face == "right" ? 1
                                                    : static_cast<int>(std::find(faces.begin() + 2, faces.end(), face) -
                                                                       faces.begin() - 2);
      if (s.has("body")) {
        const std::string body = s.string("body");
        std::vector<std::string> names;
        for (std::size_t b = 0; b < c.bodies.size(); ++b) {
          if (c.bodies[b].remove || c.bodies[b].name.empty()) continue;
          names.push_back(c.bodies[b].name);
          if (c.bodies[b].name == body) g.body = static_cast<int>(b);
        }
        if (g.body < 0)
          s.check(false, "body",
                  names.empty() ? std::string("names a [[body]] by its name, and no body has one (name = \"...\")")
                                : fmt::format("no [[body]] is called {}: the deck's are {}", escape_controls(body),
                                              escape_controls(fmt::format("{}", fmt::join(names, ", ")))));
      } else if (c.bodies.size() > 1) {
        s.check(false, "body", "a deck of several bodies says whose face it is: body = \"<its name>\"");
      }
    }
    c.gauges.push_back(g);
  }
}

// [viscosity] (ch. 6; the tensor form eqs. 7.8-7.10) and [mass_distribution] (eqs. 7.4-7.7).
void read_viscosity(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  Section v = root.optional_table("viscosity");
  c.viscosity = v.number("linear", 0.0);
  v.non_negative("linear", c.viscosity);
  c.tensor_viscosity = v.boolean("tensor", false);
  c.c_L = v.number("c_L", 1.5);
  v.non_negative("c_L", c.c_L);
  c.c_q = v.number("c_q", 2.0);
  v.non_negative("c_q", c.c_q);
  if (c.tensor_viscosity && c.viscosity > 0.0)
    v.check(false, "tensor", "choose the linear or the tensor form, not both");

  Section md = root.optional_table("mass_distribution");
  // On by default in 2-D and 3-D for every scheme: free surfaces inside the grid leave
  // nodes of tiny mass whose velocities would otherwise blow up the gradient.
  c.mass_distribution = md.boolean("on", dim > 1);
  c.mass_fraction = md.number("fraction", 0.04);
  md.check(c.mass_fraction >= 0.0 && c.mass_fraction < 1.0, "fraction", "must lie in [0, 1) (of a point's mass)");
}

// [time]: dt (or "cfl" in 2-D and 3-D) and end; returns cfl_limit.
double read_time(Section& t, MpmConfig& c) {
  const int dim = c.dim;
  if (dim > 1 && t.has("dt") && t.value_text("dt").find("cfl") != std::string::npos) {
    c.cfl_dt = t.choice("dt", {"cfl"}) == "cfl";
    c.cfl = t.number("cfl", 0.5);
    t.check(c.cfl > 0.0 && c.cfl <= 1.0, "cfl", "must lie in (0, 1]");
    c.max_volume_strain = t.number("max_volume_strain", c.max_volume_strain);
    t.check(c.max_volume_strain > 0.0 && c.max_volume_strain < 1.0, "max_volume_strain",
            "must lie in (0, 1): the most a point's volume may change in one step");
  } else {
    c.dt = t.number("dt");
    t.positive("dt", c.dt);
    for (const char* key : {"cfl", "max_volume_strain"})
      if (t.has(key))
        t.check(false, key, "only dt = \"cfl\" (2-D, 3-D) reads it; a fixed dt is checked by cfl_limit");
  }
  c.end = t.number("end");
  t.positive("end", c.end);
  const double cfl_limit = t.number("cfl_limit", 1.0);
  t.positive("cfl_limit", cfl_limit);
  c.cfl_limit = cfl_limit;
  c.energy_growth = t.number("energy_growth", 0.1);
  t.positive("energy_growth", c.energy_growth);
  c.energy_growth_stop = t.number("energy_growth_stop", std::max(1.0, c.energy_growth));
  t.check(c.energy_growth_stop >= c.energy_growth, "energy_growth_stop",
          fmt::format("must be at least energy_growth ({}): the growth that stops a run is the larger", c.energy_growth));
  return cfl_limit;
}

// [output]: record times, every, the tables, figures and VTK files.
void read_output(Section& root, MpmConfig& c) {
  const int dim = c.dim;
  Section o = root.optional_table("output");
  c.output_times = o.numbers("times", {});
  for (double x : c.output_times)
    o.check(x >= 0.0 && x <= c.end * (1 + 1e-12), "times",
            fmt::format("every time must lie in [0, time.end = {}]", c.end));
  c.output_every = o.integer("every", 0, 0, std::numeric_limits<std::int64_t>::max());
  // Every key works in every dimension or is refused there: the CSV tables are 1-D's
  // (a 2-D or 3-D run writes its points and nodes as VTK files), the figures 1-D's and 2-D's.
  c.write_nodes = o.boolean("nodes", dim == 1);
  c.write_particles = o.boolean("particles", dim == 1);
  for (const char* key : {"nodes", "particles"})
    if (dim > 1 && o.boolean(key, false))
      o.check(false, key,
              fmt::format("the CSV tables are written in 1-D only; a {}-D run writes its {} as VTK files "
                          "(output.vtk, on by default: vtk/*.vtu and particles.pvd for ParaView)",
                          dim, key[0] == 'n' ? "nodes (grid_*.vti)" : "points (particles_*.vtu)"));
  c.plot = o.boolean("plot", true);  // 3-D: checked with [convergence] (read_reference)
  c.write_vtk = o.boolean("vtk", dim > 1);
  // The x-t diagram by default where a shock user looks for it: a 1-D or quasi-1-D deck
  // with a piston or a gauge (other runs ask for it: its table is cells x 400 numbers).
  bool quasi_1d = true, shock = !c.gauges.empty();
  for (int d = 1; d < dim; ++d) quasi_1d = quasi_1d && c.cells_all[d] <= 8;
  for (const auto& side : c.boundary.face) shock = shock || side.type == BoundarySide::Type::piston;
  c.write_xt = o.boolean("xt", quasi_1d && shock);
  c.xt_every = o.integer("xt_every", 0, 0, std::numeric_limits<std::int64_t>::max());
  // md_dump = { points = [...], every = n }: the MD boxes of these points (their index in
  // the output: the `particle` column, the `id` array) as LAMMPS dumps OVITO reads.
  Section d = o.optional_table("md_dump");
  if (d.present()) {
    const bool boxes = c.material.spec && c.material.spec->atoms_per_point() > 0;
    bool any = boxes;
    for (const auto& b : c.bodies) any = any || (b.material && b.material->atoms_per_point() > 0);
    if (!any) d.error("no law of this deck runs MD boxes in its points (material.model = \"md_closure\")");
    const std::int64_t n = count_points(c);
    for (std::int64_t q : d.integers("points", 0, std::numeric_limits<std::int64_t>::max())) {
      d.check(q < n, "points", fmt::format("point {} is not one of the deck's {} points (0 to {})", q, n, n - 1));
      c.md_dump_points.push_back(q);
    }
    d.check(!c.md_dump_points.empty(), "points", "name at least one point");
    c.md_dump_every = d.integer("every", 0, 0, std::numeric_limits<std::int64_t>::max());
    c.md_dump_fields = d.strings("fields", {});
    const std::string fields_problem = md::dump_fields_problem(c.md_dump_fields);
    d.check(fields_problem.empty(), "fields", fields_problem);
  }
}

// [manufactured]: the solution that drives the run (VALIDATION.md N4).
void read_manufactured(Section& root, Section& in, MpmConfig& c) {
  const int dim = c.dim;
  const auto& mat = c.material;
  Section mf = root.optional_table("manufactured");
  if (mf.present()) {
    c.manufactured.on = true;
    mf.choice("solution", {"axis_aligned"}, "axis_aligned");
    c.manufactured.amplitude = mf.number("amplitude", 0.01);
    c.manufactured.speed = mf.number("speed", 1.0);
    mf.check(c.manufactured.amplitude > 0.0 && 2.0 * std::numbers::pi * c.manufactured.amplitude < 1.0, "amplitude",
             "must lie in (0, 1 / (2 pi)): the stretch 1 + 2 pi A cos(2 pi X) sin(c pi t) stays positive");
    mf.positive("speed", c.manufactured.speed);
    if (dim == 1) mf.error("the manufactured solution drives 2-D and 3-D decks");
    if (!mat.spec || !mat.spec->isotropic_elastic() || !c.bodies.empty())
      mf.error("the manufactured solution is exact for one linear_elastic body filling the grid (no [[body]])");
    if (in.has("velocity")) in.check(false, "velocity", "the manufactured solution sets the initial velocity");
  }
}

// [reference] and [convergence].
void read_reference(Section& root, MpmConfig& c, const std::string& deck_dir) {
  const int dim = c.dim;
  Section r = root.optional_table("reference");
  // The entry of the name (app/mpm/references.hpp) reads its own keys.
  if (r.present()) {
    c.reference.name = r.choice("name", reference_names(dim));
    c.reference.fields = r.strings("fields", {});
    const std::vector<std::string> known = References::with(
        c.reference.name, []<class E>() { return E::known_fields(); }, [] { return ReferenceEntry::known_fields(); });
    for (const auto& f : c.reference.fields)
      r.check(std::find(known.begin(), known.end(), f) != known.end(), "fields",
              fmt::format("'{}' is not one of {}", f, fmt::join(known, ", ")));
    if (dim > 1 && r.has("at")) r.check(false, "at", "2-D and 3-D decks compare at the particles");
    c.reference.times = r.numbers("times", {});
    c.reference.at_nodes = r.choice("at", {"particles", "nodes"}, "particles") == "nodes";
    References::with(
        c.reference.name, [&]<class E>() { E::read_keys(r, c, deck_dir); }, [] {});
    for (double x : c.reference.times)
      r.check(x > 0.0 && x <= c.end * (1 + 1e-12), "times",
              fmt::format("every time must lie in (0, time.end = {}]", c.end));
  }

  Section cv = root.optional_table("convergence");
  c.convergence_levels = cv.integer_int("levels", 1, 1, 8);
  if (c.convergence_levels > 1 && c.reference.name.empty())
    cv.check(false, "levels", "a convergence study needs a [reference] to measure the error against");
}

// The checks that need several tables: the CFL limit, whole steps, the law's own.
void check_time_step(Section& t, MpmConfig& c, double cfl_limit) {
  const auto& mat = c.material;
  const double dx_min = smallest_cell(c);
  if (c.upper > c.lower && c.cells >= 1 && (c.dt > 0.0 || c.cfl_dt) && mat.density > 0.0 && mat.spec) {
    const double cs_max = initial_signal_speed(c);
    const double limit = cfl_limit * dx_min / cs_max;
    if (c.cfl_dt) c.dt = first_cfl_step(c);  // the first step's; later ones follow the state
    if (std::isfinite(limit) && !c.cfl_dt && !(c.dt <= limit)) {
      // A speed typed in the wrong unit is the usual cause: its hint goes with the error.
      std::string hints;
      for (const std::string& slip : velocity_slips(c)) hints += "; " + slip;
      t.check(false, "dt",
              fmt::format("exceeds the CFL limit cfl_limit * dx / (c + v) = {} * {} / {} = {} (c the wave speed, v "
                          "the fastest point's speed: a body's velocity plus |angular_velocity| x radius, or a "
                          "piston's or a velocity face's){}",
                          cfl_limit, dx_min, cs_max, limit, hints));
    }
    // A count the run's step counter holds, before anything rounds it (1e300 / dt wrapped
    // to -9223372036854775808 steps); with dt = "cfl" the first step's dt gives its size.
    const double steps = c.end / c.dt;
    if (!(steps <= kMaxSteps))
      t.check(false, "end",
              fmt::format("is {:.4g} steps of dt = {:.4g}{}: more than the {:.0e} a run may take", steps, c.dt,
                          c.cfl_dt ? " (the CFL condition's at the start)" : "", kMaxSteps));
    else if (!c.cfl_dt && std::abs(c.dt * static_cast<double>(c.steps()) - c.end) > 1e-9 * c.end)
      t.check(false, "end", fmt::format("is not a whole number of steps of dt = {}", c.dt));
    // dt = "cfl" takes whole steps of the law's quantum (first_cfl_step): nothing to refuse.
    if (const std::string why = mat.spec && !c.cfl_dt ? mat.spec->time_step_problem(c.dt) : ""; !why.empty())
      t.check(false, "dt", why);
  }
}

// dt = "cfl" with a law whose steps are whole numbers of a quantum (md_closure's MD step):
// every step lands on the record times, so each must be a whole number of quanta too.
void check_record_quanta(Section& root, Section& t, const MpmConfig& c) {
  const double quantum = time_quantum(c);
  if (!c.cfl_dt || !(quantum > 0.0)) return;
  auto whole = [quantum](double t) {
    const double k = t / quantum;
    return std::abs(k - std::round(k)) <= 1e-6 * std::max(1.0, k);
  };
  const std::string why = fmt::format(
      "is not a whole number of MD steps of material.md.dt ({:.6g} in the deck's time unit): with dt = \"cfl\" every "
      "continuum step is a whole number of MD steps and lands on each record time",
      quantum);
  if (!whole(c.end)) t.check(false, "end", fmt::format("= {} {}", c.end, why));
  Section o = root.optional_table("output");
  for (double x : c.output_times)
    if (!whole(x)) o.check(false, "times", fmt::format("holds {}, which {}", x, why));
  Section r = root.optional_table("reference");
  for (double x : c.reference.times)
    if (!whole(x)) r.check(false, "times", fmt::format("holds {}, which {}", x, why));
}

MpmConfig read(Deck& deck) {
  MpmConfig c;
  Section root = deck.root();
  c.deck = deck.table();
  c.deck_path = deck.name();
  const std::string deck_dir = std::filesystem::path(deck.name()).parent_path().string();
  read_case(root, c);
  read_grid(root, c);
  read_particles(root, c);
  LaterWork later;
  read_bodies(root, c, deck_dir, later);
  read_scheme(root, c);
  read_materials(root, c, deck_dir, later);
  Section in = root.optional_table("initial");
  read_initial(in, c);
  read_viscosity(root, c);
  Section t = root.table("time");
  const double cfl_limit = read_time(t, c);
  read_boundary(root, c);  // after [time]: a piston's travel is checked against time.end
  read_gauges(root, c);
  read_output(root, c);
  read_manufactured(root, in, c);
  read_reference(root, c, deck_dir);
  if (Section o = root.optional_table("output"); c.dim == 3 && c.convergence_levels <= 1 && o.has("plot") && c.plot)
    o.check(false, "plot",
            "a 3-D run draws no figures but a convergence study's (open particles.pvd in ParaView; or plot = false)");
  // Every key read and its range checked: now the laws' expensive work, unless the deck
  // is refused already (its errors come at once; the checks that need the laws wait).
  const bool laws_complete = later.empty() || deck.errors().empty();
  if (laws_complete)
    for (auto& [table, work] : later) work(table);
  material_figures(c);
  if (laws_complete) {
    check_time_step(t, c, cfl_limit);
    check_record_quanta(root, t, c);
  }
  deck.finish();
  return c;
}

}  // namespace

MpmConfig read_mpm_deck(const std::string& path) {
  Deck d = Deck::from_file(path);
  return read(d);
}

MpmConfig read_mpm_deck_text(const std::string& text, const std::string& name) {
  Deck d = Deck::from_string(text, name);
  return read(d);
}

}  // namespace mpmx::app

