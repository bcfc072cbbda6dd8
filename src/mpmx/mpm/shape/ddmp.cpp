#include "mpmx/mpm/shape/ddmp.hpp"

#include <algorithm>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

DdmpTable::DdmpTable(int N, double dx) {
  const std::size_t storage = static_cast<std::size_t>(N + 1 + 2 * Grid<1>::ghost);
  for (auto* v : {&dm, &d0, &dp, &bm, &b0, &bp}) v->assign(storage, 0.0);
  for (int j = 0; j <= N; ++j) {
    const bool has_left = j >= 1, has_right = j <= N - 1;
    // V_j = int S_j dV; G_ji = int S_j dS_i/dx dV over the grid (eq. 3.28, 3.31).
    const double V = 0.5 * dx * (has_left + has_right);
    const double G_left = has_left ? -0.5 : 0.0;    // i = j - 1
    const double G_right = has_right ? 0.5 : 0.0;   // i = j + 1
    const double G_self = (has_left ? 0.5 : 0.0) + (has_right ? -0.5 : 0.0);
    const std::size_t s = static_cast<std::size_t>(j + Grid<1>::ghost);
    dm[s] = G_left / V;
    d0[s] = G_self / V;
    dp[s] = G_right / V;
    // Consistent mass of hats: dx/3 per side on the diagonal, dx/6 off it.
    bm[s] = has_left ? (dx / 6.0) / V : 0.0;
    b0[s] = (dx / 3.0) * (has_left + has_right) / V;
    bp[s] = has_right ? (dx / 6.0) / V : 0.0;
  }
  d3.resize(3 * storage);
  b3.resize(3 * storage);
  for (std::size_t s = 0; s < storage; ++s) {
    d3[3 * s] = dm[s], d3[3 * s + 1] = d0[s], d3[3 * s + 2] = dp[s];
    b3[3 * s] = bm[s], b3[3 * s + 1] = b0[s], b3[3 * s + 2] = bp[s];
  }
}

void add_ddmp_gradient(const Grid<1>& g, const DdmpTable& t, double xi, double w, int first,
                       double* out) {
  // Past the grid ends the gradient is that at the end (the point is clamped).
  const auto [c, f] = locate(clamp_to_grid(xi, g.cells[0]), g.cells[0]);
  const double inv = g.inv_dx[0];
  const double a = ddmp_alpha(f), b = 1.0 - a;
  const double Sc = 1.0 - f, Sc1 = f;
  const std::size_t jc = g.index1(c), jc1 = jc + 1;
  double* o = out + (c - 1 - first);
  o[0] += w * (b * Sc * t.dm[jc]);
  o[1] += w * (-a * inv + b * (Sc * t.d0[jc] + Sc1 * t.dm[jc1]));
  o[2] += w * (a * inv + b * (Sc * t.dp[jc] + Sc1 * t.d0[jc1]));
  o[3] += w * (b * Sc1 * t.dp[jc1]);
}

}  // namespace mpmx::mpm::shape
