#pragma once
// Wave driven into a linear elastic bar at x = L and reflected at the fixed end x = 0
// (ADMPM sec. 8.2, eqs. 8.12-8.27): v(0,t) = 0, v(L,t) = v0 sin(omega t), bar at rest
// at t = 0. Exact solution of the linearised equations 8.5 up to the moment the
// reflected front returns to x = L, i.e. for t in [0, 2L/c]; later times throw.
namespace mpmx::reference {

struct WaveReflection {
  double L = 1.0;       // bar length; the bar occupies [0, L]
  double c = 1.0;       // sound speed sqrt(Y / rho0)
  double v0 = 0.01;     // drive amplitude (v0 << c)
  double omega = 10.0;  // drive angular frequency
  double rho0 = 1.0;    // undisturbed density; Young's modulus Y = rho0 c^2
};

// Throws mpmx::InputError unless L, c, rho0 > 0, omega >= 0 and v0 finite.
void validate(const WaveReflection& w);

// Last time the solution is valid: 2L/c (times up to 2L/c (1 + 1e-12) are accepted,
// so a solver clock that rounds just past it does not throw).
double end_time(const WaveReflection& w);

// Eq. 8.21. The formulas are used as written for any x (a moving particle may sit a
// hair outside [0, L]); t must lie in [0, 2L/c], else mpmx::InputError.
double velocity(const WaveReflection& w, double x, double t);
// Eq. 8.22 (the printed signs are correct, see the .cpp): the incoming left-moving
// wave has eps = +v/c, the reflected right-moving wave eps = -v/c.
double strain(const WaveReflection& w, double x, double t);
// rho = rho0 (1 - eps) (ADMPM after eq. 8.22).
double density(const WaveReflection& w, double x, double t);
// sigma = Y eps, Y = rho0 c^2.
double stress(const WaveReflection& w, double x, double t);

// Total energy E(t) = 1/2 int_0^L (rho0 v^2 + Y eps^2) dx (eq. 8.26) of the exact
// solution: rho0 v0^2 c (t/2 - sin(2 omega t) / (4 omega)) on all of [0, 2L/c].
// This is eq. 8.27's first branch; eq. 8.27's printed second branch (t > L/c) is
// wrong (see the .cpp and tests/reference/wave_reflection_test.cpp).
double total_energy(const WaveReflection& w, double t);

}  // namespace mpmx::reference
