#include "mpmx/dpd/elastic.hpp"

#include <cmath>
#include <variant>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/particles/lattice.hpp"

namespace mpmx::dpd {

namespace {

// -U'(r) / r from the potential's eval (force over r).
double f_over_r(const PairPotential& pot, double r) {
  return std::visit(
      [r](const auto& q) {
        double e = 0, f = 0;
        q.eval(r * r, e, f);
        return f;
      },
      pot);
}

}  // namespace

LatticeConstants fcc_born_constants(const PairPotential& pot, double a) {
  const double rc = cutoff(pot);
  if (!(a > 0) || !(rc / a <= 100))
    throw InputError(fmt::format("Born constants: lattice constant {} A against a cutoff of {} A: the lattice sum "
                                 "would run over more than 100 cells per axis",
                                 a, rc));
  const int nmax = static_cast<int>(std::ceil(rc / a)) + 1;
  double c11 = 0, c12 = 0, c44 = 0, virial = 0;
  for (int i = -nmax; i <= nmax; ++i)
    for (int j = -nmax; j <= nmax; ++j)
      for (int k = -nmax; k <= nmax; ++k)
        for (const auto& b : particles::kFccBasis) {
          const double x = (i + b[0]) * a, y = (j + b[1]) * a, z = (k + b[2]) * a;
          const double r2 = x * x + y * y + z * z;
          if (r2 < 1e-12 || r2 >= rc * rc) continue;
          const double r = std::sqrt(r2);
          const double du = -f_over_r(pot, r) * r;  // U'(r)
          const double h = 1e-5 * r;
          const double d2u = (-f_over_r(pot, r + h) * (r + h) + f_over_r(pot, r - h) * (r - h)) / (2 * h);
          const double B = (d2u - du / r) / r2;
          c11 += B * x * x * x * x;
          c12 += B * x * x * y * y;
          c44 += B * x * x * y * y;
          virial += du * r;  // sum_j r U'(r)
        }
  const double omega = a * a * a / 4.0;
  LatticeConstants c;
  c.c11 = c11 / (2 * omega);
  c.c12 = c12 / (2 * omega);
  c.c44 = c44 / (2 * omega);
  c.pressure = -virial / (6 * omega);
  return c;
}

}  // namespace mpmx::dpd
