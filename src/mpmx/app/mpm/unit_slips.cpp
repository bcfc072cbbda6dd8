#include "mpmx/app/mpm/unit_slips.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "mpmx/core/file_text.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app {

namespace {

// What matter can have, in SI, and the slips (a factor too large) that explain a value
// outside it: the bounds are wide (a foam's density to osmium's, rubber's modulus to
// diamond's, the fastest flyers a gun or a laser launches) so that only a slip trips them.
struct Plausible {
  const char* what;
  const char* si_unit;
  double lo, hi;
  const char* too_large;  // the slip when the value is 1000x (density, velocity) or 1e9x (modulus) too large
  const char* too_small;
  double factor;
  const char* of = "a solid";
};

constexpr Plausible kDensity{"a density", "kg/m^3", 10.0, 3.0e4, "kg/m^3 typed for g/cm^3", "g/cm^3 typed for kg/m^3",
                             1e3};
// A gas may be as thin as it likes, never denser than the densest solid.
constexpr Plausible kGasDensity{"a density", "kg/m^3", 0.0, 3.0e4, "kg/m^3 typed for g/cm^3", "", 1e3, "a gas"};
constexpr Plausible kVelocity{"a speed", "m/s", 0.0, 5.0e4, "m/s typed for km/s", "", 1e3};
constexpr Plausible kModulus{"an elastic modulus", "Pa", 1.0e4, 2.0e12, "Pa typed for GPa", "GPa typed for Pa", 1e9};

// A deck's unit system in SI: speed, density and stress.
struct Scale {
  double velocity = 0, density = 0, stress = 0;
  std::string name;
};

std::optional<Scale> scale_of(const MpmConfig& c) {
  const auto u = units::unit_system(c.units);
  if (!u) return std::nullopt;
  // Length m, time s, stress Pa; density = stress time^2 / length^2.
  const double m = u->length_A * units::angstrom_in_m, s = u->time_ps * units::ps_in_s,
               pa = u->stress_GPa * units::GPa_in_Pa;
  return Scale{m / s, pa * s * s / (m * m), pa, std::string(u->name)};
}

void judge(std::vector<std::string>& out, const Plausible& p, const std::string& key, double value, double to_si,
           const std::string& units) {
  const double si = std::abs(value) * to_si;
  if (!std::isfinite(si) || si == 0.0 || (si >= p.lo && si <= p.hi)) return;
  const bool large = si > p.hi;
  const char* slip = large ? p.too_large : p.too_small;
  const double fixed = large ? si / p.factor : si * p.factor;
  const bool explained = *slip && fixed >= p.lo && fixed <= p.hi;
  out.push_back(fmt::format("{} = {:g} in {} is {:.3g} {}, far {} the range for {} of {} ({:g} to {:g} {}){}", key,
                            value, units, si, p.si_unit, large ? "above" : "below", p.what, p.of, p.lo, p.hi,
                            p.si_unit,
                            explained ? fmt::format(": {}? ({:g} would be {:.3g} {})", slip,
                                                    large ? value / p.factor : value * p.factor, fixed, p.si_unit)
                                      : std::string()));
}

// The law's density and its modulus: the uniaxial one it names, else density x wave
// speed^2 (a law that names none, such as cubic_elastic or mie_gruneisen).
void judge_law(std::vector<std::string>& out, const Scale& u, const std::string& where, const material::Model& law,
               int dim) {
  if (!law.solid()) {
    judge(out, kGasDensity, where + "density", law.density(), u.density, u.name);
    if (const auto gas = law.gas_law()) judge(out, kVelocity, where + "sound_speed", gas->c, u.velocity, u.name);
    return;
  }
  judge(out, kDensity, where + "density", law.density(), u.density, u.name);
  if (law.uniaxial_modulus() > 0) {
    judge(out, kModulus, where + "uniaxial modulus", law.uniaxial_modulus(), u.stress, u.name);
  } else {
    const double c = law.wave_speed(dim, law.density(), 0.0);
    judge(out, kModulus, where + "modulus (density x wave speed^2)", law.density() * c * c, u.stress, u.name);
  }
}

double norm(const std::array<double, 3>& v, int dim) {
  double s = 0;
  for (int d = 0; d < dim; ++d) s += v[d] * v[d];
  return std::sqrt(s);
}

void judge_velocities(std::vector<std::string>& out, const MpmConfig& c, const Scale& u) {
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const Body& body = c.bodies[b];
    if (body.remove) continue;
    judge(out, kVelocity, body_label(c, b) + " velocity", norm(body.velocity, c.dim), u.velocity, u.name);
    if (body.angular_velocity != 0)
      judge(out, kVelocity, body_label(c, b) + " angular_velocity x radius",
            body.angular_velocity * body.radius, u.velocity, u.name);
  }
  const Profile& v = c.velocity;
  const double fastest = std::max({std::abs(v.value) + std::abs(v.amplitude), std::abs(v.left), std::abs(v.right)});
  judge(out, kVelocity, "initial.velocity", fastest, u.velocity, u.name);
  for (int f = 0; f < 2 * c.dim; ++f) {
    const mpm::BoundarySide& side = c.boundary.face[f];
    const std::string face =
        "boundary." + std::string(c.dim == 1 ? (f == 0 ? "left" : "right") : mpm::face_name(f));
    if (side.type == mpm::BoundarySide::Type::piston) {
      double most = 0;
      for (double s : side.piston.speeds) most = std::max(most, std::abs(s));
      judge(out, kVelocity, face + ".velocity", most, u.velocity, u.name);
    } else if (side.type == mpm::BoundarySide::Type::velocity) {
      judge(out, kVelocity, face + ".value", norm(side.value, c.dim), u.velocity, u.name);
      judge(out, kVelocity, face + ".amplitude", norm(side.amplitude, c.dim), u.velocity, u.name);
    }
  }
}

}  // namespace

std::string body_label(const MpmConfig& c, std::size_t b) {
  const std::string& name = c.bodies[b].name;
  return name.empty() ? fmt::format("[[body]] {}", b)
                      : fmt::format("[[body]] {} (\"{}\")", b, escape_controls(name));
}

std::vector<std::string> velocity_slips(const MpmConfig& c) {
  std::vector<std::string> out;
  if (const auto u = scale_of(c)) judge_velocities(out, c, *u);
  return out;
}

std::vector<std::string> unit_slips(const MpmConfig& c) {
  std::vector<std::string> out;
  const auto u = scale_of(c);
  if (!u) return out;
  if (c.material.spec) judge_law(out, *u, "[material] ", *c.material.spec, c.dim);
  for (std::size_t b = 0; b < c.bodies.size(); ++b)
    if (c.bodies[b].material) judge_law(out, *u, body_label(c, b) + " [body.material] ", *c.bodies[b].material, c.dim);
  judge_velocities(out, c, *u);
  return out;
}

}  // namespace mpmx::app
