#pragma once
// Standing wave in a linear elastic bar with both ends fixed (ADMPM sec. 8.1,
// eqs. 8.9-8.10): the exact small-disturbance solution of the linearised equations
// of motion 8.5, valid for all times.
namespace mpmx::reference {

struct StandingWave {
  double L = 1.0;     // bar length; the bar occupies [0, L]
  double c = 1.0;     // sound speed sqrt(E / rho0)
  double v0 = 0.01;   // velocity amplitude (v0 << c for the linear theory to hold)
  int n = 1;          // mode number, n >= 1
  double rho0 = 1.0;  // undisturbed density
};

// Throws mpmx::InputError unless L > 0, c > 0, rho0 > 0, n >= 1 (all finite).
void validate(const StandingWave& w);

// Eq. 8.9: v(x,t) = v0 sin(n pi x / L) cos(n pi c t / L).
double velocity(const StandingWave& w, double x, double t);
// Eq. 8.10a: eps(x,t) = (v0 / c) cos(n pi x / L) sin(n pi c t / L).
double strain(const StandingWave& w, double x, double t);
// Eq. 8.10b: rho(x,t) = rho0 (1 - eps(x,t)).
double density(const StandingWave& w, double x, double t);
// Eq. 8.1c: sigma = E eps with E = rho0 c^2.
double stress(const StandingWave& w, double x, double t);

}  // namespace mpmx::reference
