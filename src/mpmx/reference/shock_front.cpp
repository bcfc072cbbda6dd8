// Shock front position and speed (ADMPM sec. 8.3, eqs. 8.28-8.29).
#include "mpmx/reference/shock_front.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

namespace {

void check_finite(std::span<const double> a, const char* what) {
  for (double v : a)
    if (!std::isfinite(v)) throw InputError(std::string("shock front: ") + what + " contains a non-finite value");
}

}  // namespace

std::optional<double> locate_front(std::span<const double> x, std::span<const double> f, double plateau_a,
                                   double plateau_b, ScanFrom from) {
  if (x.size() != f.size())
    throw InputError("shock front: " + std::to_string(x.size()) + " positions but " + std::to_string(f.size()) +
                     " values");
  if (x.size() < 2) throw InputError("shock front: need at least 2 samples to locate a front");
  check_finite(x, "x");
  check_finite(f, "f");
  if (!std::isfinite(plateau_a) || !std::isfinite(plateau_b) || plateau_a == plateau_b)
    throw InputError("shock front: the two plateau values must be finite and differ");
  const double mid = 0.5 * (plateau_a + plateau_b);

  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  if (from == ScanFrom::right) std::reverse(order.begin(), order.end());

  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const double x0 = x[order[k]], x1 = x[order[k + 1]];
    const double d0 = f[order[k]] - mid, d1 = f[order[k + 1]] - mid;
    if (d0 == 0.0) return x0;
    if ((d0 < 0.0) != (d1 < 0.0) || d1 == 0.0) return x0 + (x1 - x0) * d0 / (d0 - d1);
  }
  return std::nullopt;
}

FrontLine fit_front_line(std::span<const double> t, std::span<const double> x) {
  if (t.size() != x.size())
    throw InputError("shock front fit: " + std::to_string(t.size()) + " times but " + std::to_string(x.size()) +
                     " positions");
  if (t.size() < 2) throw InputError("shock front fit: need at least 2 (time, position) points");
  check_finite(t, "t");
  check_finite(x, "front position");
  const double n = static_cast<double>(t.size());
  const double tm = std::accumulate(t.begin(), t.end(), 0.0) / n;
  const double xm = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double stt = 0.0, stx = 0.0;  // centred sums: stable for large t
  for (std::size_t i = 0; i < t.size(); ++i) {
    stt += (t[i] - tm) * (t[i] - tm);
    stx += (t[i] - tm) * (x[i] - xm);
  }
  if (!(stt > 0.0)) throw InputError("shock front fit: all times are equal, the speed is undefined");
  const double speed = stx / stt;
  return {speed, xm - speed * tm};
}

double front_speed(std::span<const double> t, std::span<const double> x) { return fit_front_line(t, x).speed; }

}  // namespace mpmx::reference
