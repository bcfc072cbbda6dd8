#include "mpmx/core/nelder_mead.hpp"

#include <algorithm>
#include <numeric>

namespace mpmx {

NelderMeadResult nelder_mead(const std::function<double(const std::vector<double>&)>& f, std::vector<double> x0,
                             const std::vector<double>& step, int max_evaluations, double tolerance) {
  const std::size_t n = x0.size();
  std::vector<std::vector<double>> p(n + 1, x0);
  for (std::size_t k = 0; k < n; ++k) p[k + 1][k] += step[k];
  std::vector<double> v(n + 1);
  int evals = 0;
  for (std::size_t k = 0; k <= n; ++k) v[k] = f(p[k]), ++evals;
  std::vector<std::size_t> order(n + 1);
  auto point = [&](const std::vector<double>& c, const std::vector<double>& w, double t) {
    std::vector<double> r(n);
    for (std::size_t k = 0; k < n; ++k) r[k] = c[k] + t * (w[k] - c[k]);
    return r;
  };
  while (evals < max_evaluations) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    const std::size_t best = order[0], worst = order[n], second = order[n - 1];
    if (v[worst] - v[best] <= tolerance) break;
    std::vector<double> c(n, 0.0);  // centroid of all but the worst
    for (std::size_t k = 0; k <= n; ++k)
      if (k != worst)
        for (std::size_t d = 0; d < n; ++d) c[d] += p[k][d] / n;
    const auto xr = point(c, p[worst], -1.0);
    const double fr = f(xr);
    ++evals;
    if (fr < v[best]) {
      const auto xe = point(c, p[worst], -2.0);
      const double fe = f(xe);
      ++evals;
      if (fe < fr) p[worst] = xe, v[worst] = fe;
      else p[worst] = xr, v[worst] = fr;
    } else if (fr < v[second]) {
      p[worst] = xr, v[worst] = fr;
    } else {
      const bool outside = fr < v[worst];
      const auto xc = point(c, outside ? xr : p[worst], 0.5);
      const double fc = f(xc);
      ++evals;
      if (fc < (outside ? fr : v[worst])) {
        p[worst] = xc, v[worst] = fc;
      } else {  // shrink towards the best
        for (std::size_t k = 0; k <= n; ++k) {
          if (k == best) continue;
          p[k] = point(p[best], p[k], 0.5);
          v[k] = f(p[k]);
          ++evals;
        }
      }
    }
  }
  const std::size_t b = static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin());
  return {p[b], v[b], evals};
}

}  // namespace mpmx
