#include "mpmx/mpm/shape/ddmp.hpp"

#include <algorithm>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

DdmpTable::DdmpTable(const Grid<1>& g) {
  const int N = g.cells[0];
  const double dx = g.dx[0];
  dm.assign(g.storage, 0.0);
  d0.assign(g.storage, 0.0);
  dp.assign(g.storage, 0.0);
  for (int j = 0; j <= N; ++j) {
    const bool has_left = j >= 1, has_right = j <= N - 1;
    // V_j = int S_j dV; G_ji = int S_j dS_i/dx dV over the grid (eq. 3.28, 3.31).
    const double V = 0.5 * dx * (has_left + has_right);
    const double G_left = has_left ? -0.5 : 0.0;    // i = j - 1
    const double G_right = has_right ? 0.5 : 0.0;   // i = j + 1
    const double G_self = (has_left ? 0.5 : 0.0) + (has_right ? -0.5 : 0.0);
    const std::size_t s = g.index1(j);
    dm[s] = G_left / V;
    d0[s] = G_self / V;
    dp[s] = G_right / V;
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

void evaluate_ddmp(const Grid<1>& g, const DdmpTable& t, const Particles<1>& p, Stencil<1>& st) {
  const std::size_t n = p.size();
  st.reset(n, 4);
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const int cells = g.cells[0];
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    require_inside(xi, cells, q, p.x[0][q]);
    const auto [c, f] = locate(clamp_to_grid(xi, cells), cells);
    const std::size_t e = 4 * q;
    for (int k = 0; k < 4; ++k) st.node[e + k] = static_cast<int>(g.index1(c - 1 + k));
    st.S[e + 1] = 1.0 - f;
    st.S[e + 2] = f;
    add_ddmp_gradient(g, t, xi, 1.0, c - 1, &st.G[0][e]);
  }
}

void evaluate_ddmp_subpoints(const Grid<1>& g, const DdmpTable& t, const Particles<1>& p,
                             int n_sub, Stencil<1>& st) {
  const std::size_t n = p.size();
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const int cells = g.cells[0];
  // Sub-point s of particle q sits at xi_q + h (2 (s + 1/2) / n - 1), h = l/2 in cells.
  auto edge = [&](std::size_t q) { return 0.5 * p.length[0][q] * inv * (1.0 - 1.0 / n_sub); };
  int width = 4;
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    require_inside(xi, cells, q, p.x[0][q]);
    const double h = edge(q);
    const int c0 = locate(clamp_to_grid(xi - h, cells), cells).cell;
    const int c1 = locate(clamp_to_grid(xi + h, cells), cells).cell;
    width = std::max(width, c1 - c0 + 4);
  }
  st.reset(n, width);
  const double w = 1.0 / n_sub;
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    const double h = edge(q);
    const int first = locate(clamp_to_grid(xi - h, cells), cells).cell - 1;
    const std::size_t e = q * width;
    for (int k = 0; k < width; ++k)
      st.node[e + k] = static_cast<int>(g.index1(std::min(first + k, cells + Grid<1>::ghost)));
    const auto [c, f] = locate(clamp_to_grid(xi, cells), cells);
    st.S[e + (c - first)] = 1.0 - f;
    st.S[e + (c + 1 - first)] = f;
    const double step = n_sub > 1 ? 2.0 * h / (n_sub - 1) : 0.0;
    for (int s = 0; s < n_sub; ++s) add_ddmp_gradient(g, t, xi - h + s * step, w, first, &st.G[0][e]);
  }
}

}  // namespace mpmx::mpm::shape
