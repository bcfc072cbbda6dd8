#pragma once
// Nelder-Mead simplex minimisation (Nelder and Mead 1965, standard coefficients
// 1, 2, 1/2, 1/2): derivative-free, deterministic (same start, same result). Used by the
// MD-to-DPD fit.
#include <functional>
#include <vector>

namespace mpmx {

struct NelderMeadResult {
  std::vector<double> x;
  double value = 0;
  int evaluations = 0;
};

// Minimises f from x0 with initial simplex steps `step` (one per coordinate) until the
// simplex's values differ by less than `tolerance` (absolute) or `max_evaluations`.
NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, std::vector<double> x0,
                             const std::vector<double>& step, int max_evaluations = 2000,
                             double tolerance = 1e-12);

}  // namespace mpmx
