#include "mpmx/reference/manufactured.hpp"

#include <cmath>
#include <numbers>

#include "mpmx/core/error.hpp"

namespace mpmx::reference {

namespace {
constexpr double pi = std::numbers::pi;
}

void validate(const AxisAligned& m) {
  auto finite_positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!finite_positive(m.A) || 2.0 * pi * m.A >= 1.0)
    throw InputError("manufactured solution: amplitude must lie in (0, 1 / (2 pi)) so that F stays positive");
  if (!finite_positive(m.c)) throw InputError("manufactured solution: speed must be positive");
  if (!finite_positive(m.rho0)) throw InputError("manufactured solution: density must be positive");
  if (!finite_positive(m.lambda + 2.0 * m.mu))
    throw InputError("manufactured solution: lambda + 2 mu must be positive");
  if (m.dim < 1 || m.dim > 3) throw InputError("manufactured solution: dim must be 1, 2 or 3");
}

double displacement(const AxisAligned& m, double X, double t) {
  return m.A * std::sin(2.0 * pi * X) * std::sin(m.c * pi * t);
}

double velocity(const AxisAligned& m, double X, double t) {
  return m.A * m.c * pi * std::sin(2.0 * pi * X) * std::cos(m.c * pi * t);
}

double stretch(const AxisAligned& m, double X, double t) {
  return 1.0 + 2.0 * pi * m.A * std::cos(2.0 * pi * X) * std::sin(m.c * pi * t);
}

double body_force(const AxisAligned& m, const double* X, int a, double t) {
  const double s = std::sin(m.c * pi * t);
  const double acceleration = -m.A * (m.c * pi) * (m.c * pi) * std::sin(2.0 * pi * X[a]) * s;
  double J = 1.0;
  for (int b = 0; b < m.dim; ++b) J *= stretch(m, X[b], t);
  const double F = stretch(m, X[a], t);
  const double dF = -4.0 * pi * pi * m.A * std::sin(2.0 * pi * X[a]) * s;
  return acceleration - (m.lambda + 2.0 * m.mu) / m.rho0 * J * dF / (F * F);
}

}  // namespace mpmx::reference
