#pragma once
// Relative error norms of a numerical field against its reference solution, used for
// run.json's errors.<field>.l1 / .l2.
//
//   l1 = sum_i w_i |u_i - r_i|   / sum_i w_i |r_i - b|
//   l2 = sqrt( sum_i w_i (u_i - r_i)^2 / sum_i w_i (r_i - b)^2 )
//
// u: numerical values at the samples (particles), r: reference values there, w:
// weights (particle volumes, so the sums approximate integrals over the domain), b:
// the baseline, the undisturbed value of the field (0 for velocity and strain, rho0
// for density, p0 for pressure). Measuring the error relative to the disturbance r - b
// rather than to r keeps the norm meaningful for small waves on a large background
// (a density error of 1e-5 on rho0 = 1 is large when the wave is 1e-4).
#include <span>

namespace mpmx::reference {

struct ErrorNorms {
  double l1 = 0.0;
  double l2 = 0.0;
};

// Throws mpmx::InputError if the arrays differ in length or are empty, a value is not
// finite, a weight is negative, or the reference has no disturbance (sum w |r - b| = 0,
// e.g. the standing-wave strain at t = 0): the relative norm is then undefined, and a
// caller should skip that field at that time.
ErrorNorms relative_error_norms(std::span<const double> u, std::span<const double> r, std::span<const double> w,
                                double baseline);

// The disturbance's size over a run: its largest weighted mean |r - b| and RMS over the
// compared times (and its largest |r - b|, for the peak error).
struct ErrorScale {
  double mean_abs = 0.0, rms = 0.0, peak = 0.0;
};

// The same norms, relative to the larger of the disturbance now and `scale`, the
// disturbance over the run: at a time where the solution passes through its baseline
// (a standing wave's strain at a quarter period) the error is measured against the
// wave's size, not against rounding (the pointwise form gave 1e16 there).
ErrorNorms scaled_error_norms(std::span<const double> u, std::span<const double> r, std::span<const double> w,
                              double baseline, const ErrorScale& scale);
// The disturbance of r over the samples with weights w.
ErrorScale disturbance(std::span<const double> r, std::span<const double> w, double baseline);

}  // namespace mpmx::reference
