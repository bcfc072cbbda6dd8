// Exact isothermal Riemann solver (dissertation ch. 4 shock tube).
#include "mpmx/reference/riemann_isothermal.hpp"

#include <cmath>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

void validate(const IsothermalRiemann& r) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(r.c)) throw InputError("isothermal Riemann: sound speed c must be > 0, got " + std::to_string(r.c));
  if (!positive(r.left.rho))
    throw InputError("isothermal Riemann: left density must be > 0, got " + std::to_string(r.left.rho));
  if (!positive(r.right.rho))
    throw InputError("isothermal Riemann: right density must be > 0, got " + std::to_string(r.right.rho));
  if (!std::isfinite(r.left.u) || !std::isfinite(r.right.u) || !std::isfinite(r.x0))
    throw InputError("isothermal Riemann: velocities and x0 must be finite");
}

namespace {

// f(rho, rho_K) with w = ln(rho / rho_K): c w for a rarefaction (w <= 0), and for a
// shock c (rho - rho_K)/sqrt(rho rho_K) = 2 c sinh(w / 2). Both branches meet with
// value 0 and slope c at w = 0; f' >= c, and f is convex in w.
double wave_function(double w, double c) { return w <= 0.0 ? c * w : 2.0 * c * std::sinh(0.5 * w); }
double wave_slope(double w, double c) { return w <= 0.0 ? c : c * std::cosh(0.5 * w); }

IsothermalWave left_wave(const IsothermalRiemann& r, double rho, double u) {
  const IsothermalState& L = r.left;
  if (rho > L.rho) {
    // Rankine-Hugoniot s = (rho u - rho_L u_L)/(rho - rho_L); with the shock relation
    // this equals u_L - c sqrt(rho / rho_L), which has no cancellation for weak shocks.
    const double s = L.u - r.c * std::sqrt(rho / L.rho);
    return {WaveKind::shock, s, s};
  }
  return {WaveKind::rarefaction, L.u - r.c, u - r.c};
}

IsothermalWave right_wave(const IsothermalRiemann& r, double rho, double u) {
  const IsothermalState& R = r.right;
  if (rho > R.rho) {
    const double s = R.u + r.c * std::sqrt(rho / R.rho);  // = RH speed, see left_wave
    return {WaveKind::shock, s, s};
  }
  return {WaveKind::rarefaction, R.u + r.c, u + r.c};
}

}  // namespace

IsothermalStar solve_star(const IsothermalRiemann& r) {
  validate(r);
  const double c = r.c;
  const double zl = std::log(r.left.rho), zr = std::log(r.right.rho);
  const double du = r.right.u - r.left.u;
  // g(z) = f_L + f_R + (u_R - u_L) = 0; acoustic start from the linearised f = c w.
  double z = 0.5 * (zl + zr) - du / (2.0 * c);
  for (int it = 0; it < 200; ++it) {
    const double g = wave_function(z - zl, c) + wave_function(z - zr, c) + du;
    const double dg = wave_slope(z - zl, c) + wave_slope(z - zr, c);
    const double dz = g / dg;
    z -= dz;
    if (std::abs(dz) <= 1e-15 * (1.0 + std::abs(z))) break;
  }
  IsothermalStar s;
  s.rho = std::exp(z);
  // Average the two relations (they agree to rounding once Newton has converged).
  s.u = 0.5 * ((r.left.u - wave_function(z - zl, c)) + (r.right.u + wave_function(z - zr, c)));
  s.p = c * c * s.rho;
  s.left = left_wave(r, s.rho, s.u);
  s.right = right_wave(r, s.rho, s.u);
  return s;
}

IsothermalSample sample(const IsothermalRiemann& r, const IsothermalStar& star, double x, double t) {
  validate(r);
  const double c = r.c;
  auto state = [c](double rho, double u) { return IsothermalSample{rho, u, c * c * rho}; };
  if (!(t > 0.0)) return x <= r.x0 ? state(r.left.rho, r.left.u) : state(r.right.rho, r.right.u);
  const double xi = (x - r.x0) / t;
  // Speeds ordered: left.head <= left.tail < u* < right.tail <= right.head (a shock
  // has head == tail, so its "fan" interval is empty).
  if (xi < star.left.head) return state(r.left.rho, r.left.u);
  if (xi < star.left.tail) {  // inside the left fan: u = xi + c, rho = rho_L e^{-(u-u_L)/c}
    const double u = xi + c;
    return state(r.left.rho * std::exp(-(u - r.left.u) / c), u);
  }
  if (xi <= star.right.tail) return state(star.rho, star.u);
  if (xi <= star.right.head) {  // inside the right fan: u = xi - c, rho = rho_R e^{(u-u_R)/c}
    const double u = xi - c;
    return state(r.right.rho * std::exp((u - r.right.u) / c), u);
  }
  return state(r.right.rho, r.right.u);
}

IsothermalSample sample(const IsothermalRiemann& r, double x, double t) { return sample(r, solve_star(r), x, t); }

}  // namespace mpmx::reference
