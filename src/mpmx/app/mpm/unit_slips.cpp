#include "mpmx/app/mpm/unit_slips.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"

namespace mpmx::app {

namespace {

// What a solid can have, in SI, and the slips (a factor too large) that explain a value
// outside it: the bounds are wide (a foam's density to osmium's, rubber's modulus to
// diamond's, the fastest flyers a gun or a laser launches) so that only a slip trips them.
struct Plausible {
  const char* what;
  const char* si_unit;
  double lo, hi;
  const char* too_large;  // the slip when the value is 1000x (density, velocity) or 1e9x (modulus) too large
  const char* too_small;
  double factor;
};

constexpr Plausible kDensity{"a density", "kg/m^3", 10.0, 3.0e4, "kg/m^3 typed for g/cm^3", "g/cm^3 typed for kg/m^3",
                             1e3};
constexpr Plausible kVelocity{"a speed", "m/s", 0.0, 5.0e4, "m/s typed for km/s", "", 1e3};
constexpr Plausible kModulus{"an elastic modulus", "Pa", 1.0e4, 2.0e12, "Pa typed for GPa", "GPa typed for Pa", 1e9};

void judge(std::vector<std::string>& out, const Plausible& p, const std::string& key, double value, double to_si,
           const std::string& units) {
  const double si = std::abs(value) * to_si;
  if (!std::isfinite(si) || si == 0.0 || (si >= p.lo && si <= p.hi)) return;
  const bool large = si > p.hi;
  const char* slip = large ? p.too_large : p.too_small;
  const double fixed = large ? si / p.factor : si * p.factor;
  const bool explained = *slip && fixed >= p.lo && fixed <= p.hi;
  out.push_back(fmt::format("{} = {:g} in {} is {:.3g} {}, far {} the range for {} of a solid ({:g} to {:g} {}){}",
                            key, value, units, si, p.si_unit, large ? "above" : "below", p.what, p.lo, p.hi, p.si_unit,
                            explained ? fmt::format(": {}? ({:g} would be {:.3g} {})", slip,
                                                    large ? value / p.factor : value * p.factor, fixed, p.si_unit)
                                      : std::string()));
}

}  // namespace

std::vector<std::string> unit_slips(const MpmConfig& c) {
  std::vector<std::string> out;
  const auto u = units::unit_system(c.units);
  if (!u) return out;
  // The deck's units in SI: length m, time s, stress Pa; density = stress time^2 / length^2.
  const double m = u->length_A * units::angstrom_in_m, s = u->time_ps * units::ps_in_s,
               pa = u->stress_GPa * units::GPa_in_Pa;
  const double velocity = m / s, density = pa * s * s / (m * m);
  const std::string name(u->name);
  auto material = [&](const std::string& where, const material::Model& law) {
    if (!law.solid()) return;  // a gas may be as thin as it likes
    judge(out, kDensity, where + "density", law.density(), density, name);
    if (law.uniaxial_modulus() > 0) judge(out, kModulus, where + "uniaxial modulus", law.uniaxial_modulus(), pa, name);
  };
  if (c.material.spec) material("[material] ", *c.material.spec);
  for (std::size_t b = 0; b < c.bodies.size(); ++b) {
    const Body& body = c.bodies[b];
    if (body.material) material(fmt::format("[[body]] {} [body.material] ", b + 1), *body.material);
    double speed = 0;
    for (double v : body.velocity) speed += v * v;
    judge(out, kVelocity, fmt::format("[[body]] {} velocity", b + 1), std::sqrt(speed), velocity, name);
  }
  const Profile& v = c.velocity;
  const double fastest = std::max({std::abs(v.value) + std::abs(v.amplitude), std::abs(v.left), std::abs(v.right)});
  judge(out, kVelocity, "initial.velocity", fastest, velocity, name);
  return out;
}

}  // namespace mpmx::app
