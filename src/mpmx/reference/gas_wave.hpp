#pragma once
// Ideal gas driven at x = L and reflected at the closed end x = 0 (ADMPM sec. 7.7,
// eq. 7.8): v(0,t) = 0, v(L,t) = v0 sin(omega t), gas at rest at (rho0, p0) at t = 0.
// Linear acoustics, valid for t in [0, 2L/c] (later times throw).
namespace mpmx::reference {

struct GasWave {
  double L = 1.0;       // tube length; the gas occupies [0, L]
  double gamma = 1.0;   // ratio of specific heats
  double p0 = 1.0;      // undisturbed pressure
  double rho0 = 1.0;    // undisturbed density
  double v0 = 0.01;     // drive amplitude (v0 << c)
  double omega = 10.0;  // drive angular frequency
};

// Throws mpmx::InputError unless L, gamma, p0, rho0 > 0, omega >= 0 and v0 finite.
void validate(const GasWave& g);

// Eq. 7.8a: c = sqrt(gamma p0 / rho0).
double sound_speed(const GasWave& g);
// 2L/c: the last time the solution holds (up to 2L/c (1 + 1e-12) is accepted).
double end_time(const GasWave& g);

// Eq. 7.8b. Formulas are used as written for any x; t outside [0, 2L/c] throws
// mpmx::InputError.
double velocity(const GasWave& g, double x, double t);
// Acoustic pressure perturbation p' = p - p0: -rho0 c v for the incoming left-moving
// wave, +rho0 c v for the reflected right-moving one (from p_t = -rho0 c^2 v_x).
double pressure_perturbation(const GasWave& g, double x, double t);
// rho' = p' / c^2.
double density_perturbation(const GasWave& g, double x, double t);
// p0 + p' and rho0 + rho'.
double pressure(const GasWave& g, double x, double t);
double density(const GasWave& g, double x, double t);

}  // namespace mpmx::reference
