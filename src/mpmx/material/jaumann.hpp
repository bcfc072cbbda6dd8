#pragma once
// The Jaumann (co-rotational) objective stress rate of a hypoelastic law in 2-D and 3-D:
//
//   sigma_dot = C : D + W sigma - sigma W,    D = sym L,  W = skew L,  L_ab = dv_a / dx_b
//
// so that a rigid spin (D = 0) only turns the stress with the material. A step is the
// Hughes-Winget (1980) incremental rotation used symmetrically about the midpoint:
//
//   sigma^{n+1} = Rh (Rh sigma^n Rh^T + dt C : D) Rh^T,   Rh = (I - dt W / 4)^{-1} (I + dt W / 4),
//
// Rh being the Hughes-Winget rotation over half the step (the Cayley transform of
// dt W / 2, i.e. the midpoint rule applied to Q' = W Q): the rate increment is added in
// the midpoint configuration, where eq. 4.10's v^{n+1/2} gives L.
// Why this one: (1) Rh is orthogonal to round-off for any dt, so the rotation keeps
// every invariant of sigma (its eigenvalues, the norm of its deviator) to round-off,
// where a forward-Euler step of W sigma - sigma W grows the norm by up to
// sqrt(1 + (2 w dt)^2) each step (8% in one revolution at dt = T / 1000); (2) it is
// second order, also in the coupling of spin and stretch (the one-sided form
// R sigma^n R^T + dt C : D, R over the whole step, drops dt^2 [W, C : D] / 2 each step
// and is first order under simple shear); a rigid spin turns by 4 atan(w dt / 4)
// instead of w dt, a phase error of (w dt)^3 / 48 per step (5.2e-6 rad per revolution
// at dt = T / 1000), with no effect on invariants; (3) it is closed form (no
// trigonometry, no solve). The exact exponential would remove the phase error, but L
// itself is only a midpoint estimate.
//
// Tensors here are Eigen fixed-size matrices; `gather`/`scatter` move them from and to
// the point fields of Points<Dim> (row-major components [a * Dim + b]).
#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Dense>

#include "mpmx/material/points.hpp"

namespace mpmx::material::jaumann {

template <int Dim>
using Mat = Eigen::Matrix<double, Dim, Dim>;

// The tensor of point q from a row-major point field.
template <int Dim, class Ptr>
Mat<Dim> gather(const std::array<Ptr, Dim * Dim>& field, std::size_t q) {
  Mat<Dim> t;
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) t(a, b) = field[a * Dim + b][q];
  return t;
}

template <int Dim>
void scatter(const Mat<Dim>& t, std::size_t q, const std::array<double*, Dim * Dim>& field) {
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) field[a * Dim + b][q] = t(a, b);
}

// D = sym L and W = skew L; both exactly (anti)symmetric in floating point.
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> rate_of_deformation(const Mat<Dim>& L) {
  return 0.5 * (L + L.transpose());
}
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> spin(const Mat<Dim>& L) {
  return 0.5 * (L - L.transpose());
}

// The rotation terms of the Jaumann rate, W sigma - sigma W (for a law written as a
// rate; the step below integrates them).
template <int Dim>
Mat<Dim> rotation_terms(const Mat<Dim>& W, const Mat<Dim>& sigma) {
  return W * sigma - sigma * W;
}

// R = (I - A)^{-1} (I + A), A = dt W / 2, in closed form for any Dim: a skew A has
// A^3 = -theta^2 A with theta^2 = |A|_F^2 / 2, so (I - A)(I + 2 (A + A^2) / (1 + theta^2))
// = I + A. In 2-D this is the rotation by 2 atan(dt w / 2); in 1-D (A = 0) it is 1.
// For W = 0 it is the identity exactly, so a run without spin is bit-identical to the
// unrotated update.
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> hughes_winget(const Mat<Dim>& W, double dt) {
  const Mat<Dim> A = (0.5 * dt) * W;
  const double theta2 = 0.5 * A.squaredNorm();
  return Mat<Dim>::Identity() + (2.0 / (1.0 + theta2)) * (A + A * A);
}

// R S R^T: the co-rotated tensor (stress, strain, a back stress).
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> corotate(const Mat<Dim>& R, const Mat<Dim>& S) {
  return R * S * R.transpose();
}

// The half-step rotation Rh of one step dt under the spin W.
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> half_step_rotation(const Mat<Dim>& W, double dt) {
  return hughes_winget<Dim>(W, 0.5 * dt);
}

// One step of S_dot = rate + W S - S W: Rh (Rh S Rh^T + increment) Rh^T, the increment
// (dt times the rate) taken in the midpoint configuration. Anything that turns with the
// material (stress, strain, crystal axes Q: Q^{n+1} = Rh Rh Q^n) uses the same Rh.
template <int Dim>
[[gnu::always_inline]] inline Mat<Dim> objective_step(const Mat<Dim>& S, const Mat<Dim>& Rh, const Mat<Dim>& increment) {
  return corotate<Dim>(Rh, corotate<Dim>(Rh, S) + increment);
}

// The deviator S - tr(S) I / 3 of a 3x3 tensor, and its von Mises norm sqrt(3/2 s:s).
inline Mat<3> deviator(const Mat<3>& S) {
  return S - (S.trace() / 3.0) * Mat<3>::Identity();
}
inline double von_mises(const Mat<3>& S) {
  return std::sqrt(1.5 * deviator(S).squaredNorm());
}

// A Dim x Dim tensor as the top-left block of a 3x3 one, the rest zero (uniaxial strain
// in 1-D, plane strain in 2-D).
template <int Dim>
Mat<3> embed(const Mat<Dim>& t) {
  Mat<3> e = Mat<3>::Zero();
  e.template topLeftCorner<Dim, Dim>() = t;
  return e;
}

}  // namespace mpmx::material::jaumann
