// Relative l1 / l2 error norms (definition in norms.hpp).
#include "mpmx/reference/norms.hpp"

#include <cmath>
#include <string>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

ErrorNorms relative_error_norms(std::span<const double> u, std::span<const double> r, std::span<const double> w,
                                double baseline) {
  if (u.size() != r.size() || u.size() != w.size())
    throw InputError("error norms: sizes differ (numeric " + std::to_string(u.size()) + ", reference " +
                     std::to_string(r.size()) + ", weights " + std::to_string(w.size()) + ")");
  if (u.empty()) throw InputError("error norms: no samples");
  if (!std::isfinite(baseline)) throw InputError("error norms: baseline is not finite");
  double e1 = 0.0, e2 = 0.0, d1 = 0.0, d2 = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(r[i]) || !std::isfinite(w[i]))
      throw InputError("error norms: non-finite value at sample " + std::to_string(i));
    if (w[i] < 0.0) throw InputError("error norms: negative weight at sample " + std::to_string(i));
    const double e = u[i] - r[i], d = r[i] - baseline;
    e1 += w[i] * std::abs(e);
    e2 += w[i] * e * e;
    d1 += w[i] * std::abs(d);
    d2 += w[i] * d * d;
  }
  if (!(d1 > 0.0) || !(d2 > 0.0))
    throw InputError("error norms: the reference equals the baseline everywhere, the relative norm is undefined");
  return {e1 / d1, std::sqrt(e2 / d2)};
}

}  // namespace mpmx::reference
