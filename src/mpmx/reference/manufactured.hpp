#pragma once
// The axis-aligned manufactured displacement of Wallstedt and Guilkey (2008), made exact
// for the hypoelastic linear law of material/linear_elastic.hpp. On every axis a,
//   u_a(X, t) = A sin(2 pi X_a) sin(c pi t)
// in the material coordinate X. The motion is a pure stretch, F = diag(F_aa) with
// F_aa = 1 + 2 pi A cos(2 pi X_a) sin(c pi t): no spin, so the Jaumann rate is the plain
// rate and sigma_dot = lambda tr(D) I + 2 mu D integrates to the Hencky form
//   sigma_aa = lambda sum_b ln F_bb + 2 mu ln F_aa,  sigma_ab = 0 (a != b).
// The body force (per unit mass) that makes it a solution of rho a = div sigma + rho b:
//   b_a = d2u_a/dt2 - (lambda + 2 mu) / rho0 * J * (dF_aa/dX_a) / F_aa^2,  J = prod_b F_bb.
namespace mpmx::reference {

struct AxisAligned {
  double A = 0.01;      // displacement amplitude (unit cell [0, 1]^dim)
  double c = 1.0;       // time scale: u oscillates as sin(c pi t)
  double lambda = 0.0;  // Lame constants of the law (plane strain in 2-D)
  double mu = 0.0;
  double rho0 = 1.0;
  int dim = 2;
};

// Throws mpmx::InputError unless A > 0 and small enough that F stays positive
// (2 pi A < 1), c > 0, rho0 > 0, lambda + 2 mu > 0, dim in 1..3.
void validate(const AxisAligned& m);

double displacement(const AxisAligned& m, double X, double t);  // u_a of one axis
double velocity(const AxisAligned& m, double X, double t);      // du_a/dt
double stretch(const AxisAligned& m, double X, double t);       // F_aa
// b_a at material point X (dim coordinates) and time t.
double body_force(const AxisAligned& m, const double* X, int a, double t);

}  // namespace mpmx::reference
