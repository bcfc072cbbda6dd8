#pragma once
// Shock-front helpers for the A3 "small shock" case (ADMPM sec. 8.3, eqs. 8.28-8.31):
// where a front sits at one time, and how fast it moves. ADMPM estimates the speed by
// averaging finite differences (eq. 8.29); a least-squares line is used here instead,
// as that text itself recommends.
#include <optional>
#include <span>

namespace mpmx::reference {

enum class ScanFrom { left, right };

// The position of a front in samples (x_i, f_i) of one field at one time: the first
// place, scanning from `from`, where f crosses the midpoint m = (plateau_a + plateau_b)/2
// of the two plateau values on either side of the front, linearly interpolated between
// the two samples that bracket m. The samples need not be sorted (they are ordered by
// x here). Scan from the undisturbed side so that oscillations behind the front are not
// taken for it. Returns std::nullopt when f never reaches m. Throws mpmx::InputError if
// x and f differ in length, fewer than 2 samples are given, a value is not finite, or
// plateau_a == plateau_b.
std::optional<double> locate_front(std::span<const double> x, std::span<const double> f, double plateau_a,
                                   double plateau_b, ScanFrom from);

// Least-squares line x_front = x0 + speed t through (t_i, x_i).
struct FrontLine {
  double speed = 0.0;
  double x0 = 0.0;  // intercept at t = 0
};

// Throws mpmx::InputError if t and x differ in length, fewer than 2 points are given,
// a value is not finite, or all t are equal.
FrontLine fit_front_line(std::span<const double> t, std::span<const double> x);
// fit_front_line(t, x).speed (eq. 8.28 predicts c for a weak shock).
double front_speed(std::span<const double> t, std::span<const double> x);

}  // namespace mpmx::reference
