// Relative l1 / l2 error norms (definition in norms.hpp).
#include "mpmx/reference/norms.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

ErrorNorms relative_error_norms(std::span<const double> u, std::span<const double> r, std::span<const double> w,
                                double baseline) {
  return scaled_error_norms(u, r, w, baseline, {});
}

ErrorScale disturbance(std::span<const double> r, std::span<const double> w, double baseline) {
  ErrorScale s;
  double wsum = 0.0, d1 = 0.0, d2 = 0.0;
  for (std::size_t i = 0; i < r.size() && i < w.size(); ++i) {
    const double d = r[i] - baseline;
    wsum += w[i], d1 += w[i] * std::abs(d), d2 += w[i] * d * d;
    s.peak = std::max(s.peak, std::abs(d));
  }
  if (wsum > 0.0) s.mean_abs = d1 / wsum, s.rms = std::sqrt(d2 / wsum);
  return s;
}

ErrorNorms scaled_error_norms(std::span<const double> u, std::span<const double> r, std::span<const double> w,
                              double baseline, const ErrorScale& scale) {
  if (u.size() != r.size() || u.size() != w.size())
    throw InputError("error norms: sizes differ (numeric " + std::to_string(u.size()) + ", reference " +
                     std::to_string(r.size()) + ", weights " + std::to_string(w.size()) + ")");
  if (u.empty()) throw InputError("error norms: no samples");
  if (!std::isfinite(baseline)) throw InputError("error norms: baseline is not finite");
  double e1 = 0.0, e2 = 0.0, d1 = 0.0, d2 = 0.0, wsum = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(r[i]) || !std::isfinite(w[i]))
      throw InputError("error norms: non-finite value at sample " + std::to_string(i));
    if (w[i] < 0.0) throw InputError("error norms: negative weight at sample " + std::to_string(i));
    const double e = u[i] - r[i], d = r[i] - baseline;
    e1 += w[i] * std::abs(e);
    e2 += w[i] * e * e;
    d1 += w[i] * std::abs(d);
    d2 += w[i] * d * d;
    wsum += w[i];
  }
  // Over the weights' sum: means, comparable with the scale's.
  const double s1 = std::max(wsum > 0.0 ? d1 / wsum : 0.0, scale.mean_abs);
  const double s2 = std::max(wsum > 0.0 ? d2 / wsum : 0.0, scale.rms * scale.rms);
  if (!(s1 > 0.0) || !(s2 > 0.0))
    throw InputError("error norms: the reference equals the baseline everywhere, the relative norm is undefined");
  return {e1 / wsum / s1, std::sqrt(e2 / wsum / s2)};
}

}  // namespace mpmx::reference
