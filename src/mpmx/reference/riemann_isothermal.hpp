#pragma once
// Exact solution of the isothermal Riemann problem (p = c^2 rho, c constant): the
// shock tube of the dissertation, ch. 4 (partition removed at t = 0, left pressure
// slightly higher). Two waves (no contact: the temperature is the same everywhere)
// separate the left state, one star state (rho*, u*) and the right state. Each wave is
// a shock when rho* exceeds the density ahead of it, else a rarefaction:
//   left:  u* = u_L - f(rho*, rho_L),  right: u* = u_R + f(rho*, rho_R),
//   f(rho, rho_K) = c ln(rho / rho_K)                  (rarefaction, rho <= rho_K)
//                 = c (rho - rho_K) / sqrt(rho rho_K)  (shock, rho > rho_K).
// Isothermal rarefactions never reach vacuum, so a star state always exists.
namespace mpmx::reference {

struct IsothermalState {
  double rho = 1.0;  // density, > 0
  double u = 0.0;    // velocity
};

struct IsothermalRiemann {
  IsothermalState left;
  IsothermalState right;
  double c = 1.0;   // isothermal sound speed, p = c^2 rho
  double x0 = 0.0;  // initial interface position
};

enum class WaveKind { shock, rarefaction };

// One wave: a shock has head == tail == its Rankine-Hugoniot speed
// s = (rho* u* - rho_K u_K) / (rho* - rho_K); a rarefaction fan spans the speeds
// [head, tail] (left: u_L - c .. u* - c, right: u* + c .. u_R + c; head is the edge
// facing the undisturbed state).
struct IsothermalWave {
  WaveKind kind = WaveKind::rarefaction;
  double head = 0.0;
  double tail = 0.0;
};

struct IsothermalStar {
  double rho = 1.0;  // star density (continuous across the middle: no contact wave)
  double u = 0.0;    // star velocity
  double p = 1.0;    // c^2 rho
  IsothermalWave left;
  IsothermalWave right;
};

struct IsothermalSample {
  double rho = 1.0;
  double u = 0.0;
  double p = 1.0;
};

// Throws mpmx::InputError unless c > 0 and both densities > 0 (all finite).
void validate(const IsothermalRiemann& r);

// Newton iteration in z = ln rho* (the equation is increasing and convex in z, so it
// converges from any start) to machine precision.
IsothermalStar solve_star(const IsothermalRiemann& r);

// The solution at (x, t); t <= 0 gives the initial data (x0 itself belongs to the
// left). Pass the result of solve_star(r) to avoid solving again at every sample.
IsothermalSample sample(const IsothermalRiemann& r, const IsothermalStar& star, double x, double t);
IsothermalSample sample(const IsothermalRiemann& r, double x, double t);

}  // namespace mpmx::reference
