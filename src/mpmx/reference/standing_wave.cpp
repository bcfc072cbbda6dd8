// Standing wave, ADMPM eqs. 8.9-8.10.
#include "mpmx/reference/standing_wave.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

void validate(const StandingWave& w) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(w.L)) throw InputError("standing wave: length L must be > 0, got " + std::to_string(w.L));
  if (!positive(w.c)) throw InputError("standing wave: sound speed c must be > 0, got " + std::to_string(w.c));
  if (!positive(w.rho0)) throw InputError("standing wave: density rho0 must be > 0, got " + std::to_string(w.rho0));
  if (!std::isfinite(w.v0)) throw InputError("standing wave: amplitude v0 must be finite");
  if (w.n < 1) throw InputError("standing wave: mode number n must be >= 1, got " + std::to_string(w.n));
}

namespace {
double wavenumber(const StandingWave& w) { return w.n * std::numbers::pi / w.L; }
}  // namespace

double velocity(const StandingWave& w, double x, double t) {
  validate(w);
  const double k = wavenumber(w);
  return w.v0 * std::sin(k * x) * std::cos(k * w.c * t);  // eq. 8.9
}

double strain(const StandingWave& w, double x, double t) {
  validate(w);
  const double k = wavenumber(w);
  return w.v0 / w.c * std::cos(k * x) * std::sin(k * w.c * t);  // eq. 8.10a
}

double density(const StandingWave& w, double x, double t) {
  return w.rho0 * (1.0 - strain(w, x, t));  // eq. 8.10b
}

double stress(const StandingWave& w, double x, double t) {
  return w.rho0 * w.c * w.c * strain(w, x, t);  // eq. 8.1c, E = rho0 c^2
}

}  // namespace mpmx::reference
