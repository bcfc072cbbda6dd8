// Ideal-gas wave, ADMPM eq. 7.8, with the pressure and density profiles the seed only
// calls "similar": linear acoustics rho0 v_t = -p_x, p_t = -rho0 c^2 v_x. A wave
// f(x + c t) (moving in -x) has p' = -rho0 c v; a wave f(x - c t) has p' = +rho0 c v.
// Isentropic perturbation: rho' = p' / c^2.
#include "mpmx/reference/gas_wave.hpp"

#include <cmath>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

void validate(const GasWave& g) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(g.L)) throw InputError("gas wave: length L must be > 0, got " + std::to_string(g.L));
  if (!positive(g.gamma)) throw InputError("gas wave: gamma must be > 0, got " + std::to_string(g.gamma));
  if (!positive(g.p0)) throw InputError("gas wave: pressure p0 must be > 0, got " + std::to_string(g.p0));
  if (!positive(g.rho0)) throw InputError("gas wave: density rho0 must be > 0, got " + std::to_string(g.rho0));
  if (!std::isfinite(g.omega) || g.omega < 0.0)
    throw InputError("gas wave: drive frequency omega must be >= 0, got " + std::to_string(g.omega));
  if (!std::isfinite(g.v0)) throw InputError("gas wave: amplitude v0 must be finite");
}

double sound_speed(const GasWave& g) {
  validate(g);
  return std::sqrt(g.gamma * g.p0 / g.rho0);  // eq. 7.8a
}

double end_time(const GasWave& g) { return 2.0 * g.L / sound_speed(g); }

namespace {

// Velocity of the incoming and of the reflected component at (x, t).
struct Components {
  double v_in, v_r;
};

Components components(const GasWave& g, double x, double t) {
  const double c = sound_speed(g);
  const double t_end = 2.0 * g.L / c;
  if (!(t >= 0.0 && t <= t_end * (1.0 + 1e-12)))
    throw InputError("gas wave: the analytic solution (ADMPM eq. 7.8) holds for t in [0, 2L/c] = [0, " +
                     std::to_string(t_end) + "], got t = " + std::to_string(t));
  Components k{0.0, 0.0};
  if (x > g.L - c * t) k.v_in = g.v0 * std::sin(g.omega * ((x - g.L) / c + t));   // eq. 7.8b
  if (x < c * t - g.L) k.v_r = -g.v0 * std::sin(g.omega * (t - (x + g.L) / c));  // reflection
  return k;
}

}  // namespace

double velocity(const GasWave& g, double x, double t) {
  const Components k = components(g, x, t);
  return k.v_in + k.v_r;  // on the left, 2 v0 sin(omega x/c) cos(omega(t - L/c)), eq. 7.8b
}

double pressure_perturbation(const GasWave& g, double x, double t) {
  const Components k = components(g, x, t);
  const double z = g.rho0 * sound_speed(g);  // acoustic impedance
  // Left-moving incoming wave: p' = -z v; right-moving reflected wave: p' = +z v.
  // Where both exist: -2 z v0 cos(omega x / c) sin(omega (t - L/c)).
  return -z * k.v_in + z * k.v_r;
}

double density_perturbation(const GasWave& g, double x, double t) {
  const double c = sound_speed(g);
  return pressure_perturbation(g, x, t) / (c * c);
}

double pressure(const GasWave& g, double x, double t) { return g.p0 + pressure_perturbation(g, x, t); }

double density(const GasWave& g, double x, double t) { return g.rho0 + density_perturbation(g, x, t); }

}  // namespace mpmx::reference
