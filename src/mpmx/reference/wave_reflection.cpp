// Driven-and-reflected wave, ADMPM eqs. 8.21, 8.22, 8.26/8.27.
//
// Structure of the solution. With phase a = omega((x - L)/c + t) the driven wave is
// v_in = v0 sin(a), a function of x + c t, i.e. a wave moving in -x. For u = g(x + c t)
// the strain u_x = g' and the velocity u_t = c g', so eps_in = +v_in / c: the sign
// printed in eq. 8.22 (second and fourth branches) is right. The reflected wave
// (eq. 8.17) v_r = -v0 sin(b), b = omega(t - (x + L)/c), moves in +x, so eps_r = -v_r/c
// = +(v0/c) sin(b), and eps_in + eps_r = 2 (v0/c) cos(omega x / c) sin(omega(t - L/c)),
// eq. 8.22's third branch. Both satisfy rho0 v_t = Y eps_x and eps_t = v_x (eq. 8.5),
// checked by finite differences in the test.
//
// Energy. Each travelling wave has energy density rho0 v^2 (kinetic = strain energy).
// Where both waves overlap (x < ct - L) the cross terms cancel:
//   1/2 rho0 v0^2 [(sin a - sin b)^2 + (sin a + sin b)^2] = rho0 v0^2 (sin^2 a + sin^2 b).
// Substituting s = a/omega, resp. s = b/omega (dx = c ds) turns the two integrals into
// c int_{t-L/c}^{t} sin^2(omega s) ds + c int_0^{t-L/c} sin^2(omega s) ds
//   = c int_0^t sin^2(omega s) ds,
// so E(t) = rho0 v0^2 c (t/2 - sin(2 omega t)/(4 omega)) for ALL t in [0, 2L/c]. The
// same follows from the work done by the drive: dE/dt = sigma(L,t) v(L,t)
// = rho0 c v0^2 sin^2(omega t), since the reflected front has not yet reached x = L.
// Eq. 8.27's printed second branch, t/2 - sin(omega(t - 2L/c)) cos(omega(3t - 2L/c))
// /(2 omega) - sin(4 omega (t - L/c))/(8 omega), is not continuous with the first at
// t = L/c (it gives t/2 + sin(2 omega L/c)/(4 omega) there) and disagrees with the
// integral of eq. 8.26; the test integrates eq. 8.26 numerically and shows both.
#include "mpmx/reference/wave_reflection.hpp"

#include <cmath>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

void validate(const WaveReflection& w) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(w.L)) throw InputError("wave reflection: length L must be > 0, got " + std::to_string(w.L));
  if (!positive(w.c)) throw InputError("wave reflection: sound speed c must be > 0, got " + std::to_string(w.c));
  if (!positive(w.rho0))
    throw InputError("wave reflection: density rho0 must be > 0, got " + std::to_string(w.rho0));
  if (!std::isfinite(w.omega) || w.omega < 0.0)
    throw InputError("wave reflection: drive frequency omega must be >= 0, got " + std::to_string(w.omega));
  if (!std::isfinite(w.v0)) throw InputError("wave reflection: amplitude v0 must be finite");
}

double end_time(const WaveReflection& w) {
  validate(w);
  return 2.0 * w.L / w.c;
}

namespace {

void check_time(const WaveReflection& w, double t) {
  const double t_end = end_time(w);
  if (!(t >= 0.0 && t <= t_end * (1.0 + 1e-12)))
    throw InputError("wave reflection: the analytic solution (ADMPM eq. 8.21) holds for t in [0, 2L/c] = [0, " +
                     std::to_string(t_end) + "], got t = " + std::to_string(t));
}

// Incoming (left-moving) and reflected (right-moving) components; the reflected one is
// zero until its front x = ct - L has passed x.
struct Components {
  double v_in, eps_in, v_r, eps_r;
};

Components components(const WaveReflection& w, double x, double t) {
  check_time(w, t);
  Components k{0.0, 0.0, 0.0, 0.0};
  if (x > w.L - w.c * t) {  // incoming front has passed (eqs. 8.14, 8.21)
    const double a = w.omega * ((x - w.L) / w.c + t);
    k.v_in = w.v0 * std::sin(a);
    k.eps_in = k.v_in / w.c;  // left-moving: eps = +v/c
  }
  if (x < w.c * t - w.L) {  // reflected front has passed (eqs. 8.15-8.17)
    const double b = w.omega * (t - (x + w.L) / w.c);
    k.v_r = -w.v0 * std::sin(b);  // eq. 8.17
    k.eps_r = -k.v_r / w.c;       // right-moving: eps = -v/c
  }
  return k;
}

}  // namespace

double velocity(const WaveReflection& w, double x, double t) {
  const Components k = components(w, x, t);
  return k.v_in + k.v_r;  // eq. 8.21 (third branch = eq. 8.20)
}

double strain(const WaveReflection& w, double x, double t) {
  const Components k = components(w, x, t);
  return k.eps_in + k.eps_r;  // eq. 8.22
}

double density(const WaveReflection& w, double x, double t) { return w.rho0 * (1.0 - strain(w, x, t)); }

double stress(const WaveReflection& w, double x, double t) { return w.rho0 * w.c * w.c * strain(w, x, t); }

double total_energy(const WaveReflection& w, double t) {
  check_time(w, t);
  const double base = w.rho0 * w.v0 * w.v0 * w.c;
  if (w.omega == 0.0) return 0.0;  // no drive, no wave
  // c int_0^t sin^2(omega s) ds, see the comment at the top (eq. 8.27, first branch).
  return base * (0.5 * t - std::sin(2.0 * w.omega * t) / (4.0 * w.omega));
}

}  // namespace mpmx::reference
