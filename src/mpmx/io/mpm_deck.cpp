#include "mpmx/io/mpm_deck.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/config.hpp"

namespace mpmx::io {

namespace {

using mpm::BoundarySide;
using mpm::MpmConfig;
using mpm::Profile;

const std::vector<std::string> kMaterials{"linear_elastic", "ideal_gas_isothermal",
                                          "ideal_gas_adiabatic", "md_closure"};
const std::vector<std::string> kReferences{"standing_wave", "wave_reflection", "gas_wave",
                                           "riemann_isothermal", "shock_front", "direct_md"};

Profile read_profile(Section s, double fallback) {
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
  return p;
}

BoundarySide read_side(Section s) {
  BoundarySide b;
  if (!s.present()) return b;
  const std::string type = s.choice("type", {"free", "fixed", "velocity"}, "free");
  b.type = type == "free" ? BoundarySide::Type::free
           : type == "fixed" ? BoundarySide::Type::fixed
                             : BoundarySide::Type::velocity;
  if (b.type == BoundarySide::Type::velocity) {
    b.value = s.number("value", 0.0);
    b.amplitude = s.number("amplitude", 0.0);
    b.omega = s.number("omega", 0.0);
  }
  return b;
}

// [material] of an md_closure: [material.potential] and [material.md]; the crystal's
// density and C11 (continuum units) come from the potential itself.
void read_md_closure(Section m, const std::string& deck_dir, const std::string& unit_name,
                     mpm::MaterialConfig& mat) {
  auto& md = mat.md;
  const auto u = units::unit_system(unit_name);
  if (u) md.units = *u;
  else
    m.check(false, "model",
            fmt::format("md_closure needs case.units to be one of {}, not '{}'", units::unit_system_names(),
                        unit_name));
  md.potential = md::read_potential(m.table("potential"), deck_dir);
  Section s = m.table("md");
  md.cells = static_cast<int>(s.integer("cells", 4));
  s.check(md.cells >= 1 && md.cells <= 20, "cells", "must be from 1 to 20 (4 x cells^3 atoms per point)");
  md.temperature = s.number("temperature", 0.0);
  s.non_negative("temperature", md.temperature);
  const auto seed = s.integer("seed", 1);
  s.check(seed >= 0, "seed", "must be >= 0");
  md.seed = static_cast<std::uint64_t>(seed);
  md.dt = s.number("dt", 0.001);
  s.positive("dt", md.dt);
  s.check(md.dt <= 0.01, "dt", "is above 0.01 ps; metal MD needs about 0.001 ps");
  md.relax_steps = s.integer("relax_steps", 0);
  s.check(md.relax_steps >= 0, "relax_steps", "must be >= 0");
  md.sample = s.choice("stress", {"last", "average"}, "last") == "last" ? multiscale::StressSample::last
                                                                        : multiscale::StressSample::average;
  md.skin = s.number("skin", 1.0);
  s.non_negative("skin", md.skin);
  md.mixed_precision = s.choice("precision", {"double", "mixed"}, "double") == "mixed";
  mat.density_unstrained = true;
  if (md.potential.style != "eam" || !md.potential.file.empty()) {
    try {
      const auto props = material::md_closure_properties(md.potential, md.units);
      mat.density = props.density;
      mat.youngs_modulus = props.modulus;
    } catch (const std::exception& e) {
      m.check(false, "potential", e.what());
    }
  }
}

// Largest initial sound speed, for the CFL limit.
double initial_sound_speed(const MpmConfig& c) {
  const auto& m = c.material;
  if (m.model == "md_closure") return std::sqrt(m.youngs_modulus / m.density);
  if (m.model == "linear_elastic") {
    const double nu = c.dim == 1 ? 0.0 : m.poisson_ratio;
    const double M = c.dim == 1 ? m.youngs_modulus
                                : m.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    return std::sqrt(std::max(M, 0.0) / m.density);
  }
  if (m.model == "ideal_gas_isothermal") return m.sound_speed;
  // Adiabatic: the largest of sqrt(gamma p / rho) over the initial pressure profile.
  double pmax = 0.0;
  const double L = c.upper - c.lower;
  for (int i = 0; i <= 4 * c.cells; ++i) {
    const double x = c.lower + L * i / (4.0 * c.cells);
    pmax = std::max(pmax, c.pressure(x, c.lower, L, c.dx()));
  }
  return std::sqrt(m.gamma * pmax / m.density);
}

MpmConfig read(Deck& deck) {
  MpmConfig c;
  Section root = deck.root();
  c.deck = deck.table();
  c.deck_path = deck.name();

  Section cs = root.table("case");
  c.id = cs.string("id");
  c.title = cs.string("title", "");
  c.seed = cs.string("seed", "");
  c.units = cs.string("units", "consistent units");
  const std::string deck_dir = std::filesystem::path(deck.name()).parent_path().string();

  Section g = root.table("grid");
  c.dim = static_cast<int>(g.integer("dim", 1));
  g.check(c.dim == 1, "dim", "this version runs 1-D continuum decks (2-D and 3-D come later)");
  c.lower = g.number("lower", 0.0);
  c.upper = g.number("upper");
  g.check(c.upper > c.lower, "upper", fmt::format("must exceed grid.lower = {}", c.lower));
  c.cells = static_cast<int>(g.integer("cells"));
  g.check(c.cells >= 1, "cells", "must be at least 1");

  Section pt = root.table("particles");
  c.per_cell = static_cast<int>(pt.integer("per_cell", 2));
  pt.check(c.per_cell >= 1, "per_cell", "must be at least 1");
  c.move = pt.boolean("move", true);

  Section sc = root.table("scheme");
  const std::string name = sc.choice("name", mpm::scheme_names());
  c.scheme.scheme = mpm::scheme_from_name(name);
  if (c.scheme.scheme == mpm::Scheme::ddmp_subpoints) {
    c.scheme.subpoints = static_cast<int>(sc.integer("subpoints"));
    sc.check(c.scheme.subpoints >= 1, "subpoints", "must be at least 1");
  } else if (sc.has("subpoints")) {
    sc.check(false, "subpoints", fmt::format("only ddmp_subpoints uses sub-points, not {}", name));
  }
  c.scheme.midpoint_gradient =
      sc.choice("update_velocity", {"midpoint", "updated"}, "midpoint") == "midpoint";

  Section m = root.table("material");
  auto& mat = c.material;
  mat.model = m.choice("model", kMaterials);
  if (mat.model != "md_closure") {  // the closure's density is its crystal's
    mat.density = m.number("density", 1.0);
    m.positive("density", mat.density);
  }
  mat.small_strain = m.boolean("small_strain", false);
  if (mat.model == "linear_elastic") {
    mat.youngs_modulus = m.number("youngs_modulus");
    m.positive("youngs_modulus", mat.youngs_modulus);
    mat.poisson_ratio = m.number("poisson_ratio", 0.0);
    m.check(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5, "poisson_ratio",
            "must lie in (-1, 0.5)");
    mat.density_unstrained = m.choice("density_of", {"initial", "unstrained"}, "initial") == "unstrained";
  } else if (mat.model == "md_closure") {
    read_md_closure(m, deck_dir, c.units, mat);
  } else if (mat.model == "ideal_gas_isothermal") {
    mat.sound_speed = m.number("sound_speed");
    m.positive("sound_speed", mat.sound_speed);
  } else {
    mat.gamma = m.number("gamma", 1.4);
    m.check(mat.gamma > 1.0, "gamma", "must exceed 1");
  }

  Section in = root.optional_table("initial");
  c.velocity = read_profile(in.optional_table("velocity"), 0.0);
  const bool solid = mat.solid();
  if (solid) {
    c.strain = read_profile(in.optional_table("strain"), 0.0);
    if (in.has("pressure")) in.check(false, "pressure", "a solid takes [initial.strain], not pressure");
  } else {
    const double p_default =
        mat.model == "ideal_gas_isothermal" ? mat.sound_speed * mat.sound_speed * mat.density : 1.0;
    c.pressure = read_profile(in.optional_table("pressure"), p_default);
    if (in.has("strain")) in.check(false, "strain", "a gas takes [initial.pressure], not strain");
  }

  Section b = root.optional_table("boundary");
  c.boundary.left = read_side(b.optional_table("left"));
  c.boundary.right = read_side(b.optional_table("right"));

  Section v = root.optional_table("viscosity");
  c.viscosity = v.number("linear", 0.0);
  v.non_negative("linear", c.viscosity);

  Section t = root.table("time");
  c.dt = t.number("dt");
  t.positive("dt", c.dt);
  c.end = t.number("end");
  t.positive("end", c.end);
  const double cfl_limit = t.number("cfl_limit", 1.0);
  t.positive("cfl_limit", cfl_limit);

  Section o = root.optional_table("output");
  c.output_times = o.numbers("times", {});
  for (double x : c.output_times)
    o.check(x >= 0.0 && x <= c.end * (1 + 1e-12), "times",
            fmt::format("every time must lie in [0, time.end = {}]", c.end));
  c.output_every = o.integer("every", 0);
  o.check(c.output_every >= 0, "every", "must not be negative");
  c.write_nodes = o.boolean("nodes", true);
  c.write_particles = o.boolean("particles", true);
  c.plot = o.boolean("plot", true);

  Section r = root.optional_table("reference");
  if (r.present()) {
    c.reference.name = r.choice("name", kReferences);
    c.reference.fields = r.strings("fields", {});
    const std::vector<std::string> known{"velocity", "strain", "stress", "pressure", "density"};
    for (const auto& f : c.reference.fields)
      r.check(std::find(known.begin(), known.end(), f) != known.end(), "fields",
              fmt::format("'{}' is not one of velocity, strain, stress, pressure, density", f));
    c.reference.times = r.numbers("times", {});
    c.reference.at_nodes = r.choice("at", {"particles", "nodes"}, "particles") == "nodes";
    if (c.reference.name == "direct_md") {
      const std::filesystem::path f = r.string("file");
      c.reference.file = f.is_absolute() || deck_dir.empty() ? f.string() : (deck_dir / f).string();
      r.check(units::unit_system(c.units).has_value(), "name",
              fmt::format("direct_md needs case.units to be one of {} (the MD side is in Angstrom, ps, GPa)",
                          units::unit_system_names()));
      if (c.reference.fields.empty()) c.reference.fields = {"stress"};
    } else if (r.has("file")) {
      r.check(false, "file", "only reference direct_md reads a file");
    }
    for (double x : c.reference.times)
      r.check(x > 0.0 && x <= c.end * (1 + 1e-12), "times",
              fmt::format("every time must lie in (0, time.end = {}]", c.end));
  }

  // Checks that need several sections.
  if (c.upper > c.lower && c.cells >= 1 && c.dt > 0.0 && mat.density > 0.0) {
    const double cs_max = initial_sound_speed(c);
    const double limit = cfl_limit * c.dx() / cs_max;
    if (std::isfinite(limit))
      t.check(c.dt <= limit, "dt",
              fmt::format("exceeds the CFL limit cfl_limit * dx / c = {} * {} / {} = {}", cfl_limit,
                          c.dx(), cs_max, limit));
    if (std::abs(c.dt * std::llround(c.end / c.dt) - c.end) > 1e-9 * c.end)
      t.check(false, "end", fmt::format("is not a whole number of steps of dt = {}", c.dt));
    if (mat.model == "md_closure" && mat.md.dt > 0)
      t.check(mat.md.md_steps(c.dt) > 0, "dt",
              fmt::format("is {} ps, not a whole number of MD steps of material.md.dt = {} ps",
                          c.dt * mat.md.units.time_ps, mat.md.dt));
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

}  // namespace mpmx::io

