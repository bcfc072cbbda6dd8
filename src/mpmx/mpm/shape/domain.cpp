// Finite-domain schemes in 1-D: uGIMP/cpGIMP (domain average, eq. 3.17-3.18) and CPDI
// (corner average, eq. 3.23-3.24). Which length the domain has (fixed or deformed)
// is decided by the caller through Particles::length.
#include "mpmx/mpm/shape/domain.hpp"

#include <algorithm>
#include <cmath>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

void evaluate_domain(const Grid<1>& g, const Particles<1>& p, Stencil<1>& st, bool integrate) {
  const std::size_t n = p.size();
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const int cells = g.cells[0];
  // Width: nodes floor(xi_a) .. floor(xi_b) + 1 of the widest particle.
  int width = 2;
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    require_inside(xi, cells, q, p.x[0][q]);
    const double h = 0.5 * p.length[0][q] * inv;
    width = std::max(width, static_cast<int>(std::floor(clamp_to_grid(xi + h, cells)) -
                                             std::floor(clamp_to_grid(xi - h, cells))) + 2);
  }
  st.reset(n, width);
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    const double h = 0.5 * p.length[0][q] * inv;
    const double a = xi - h, b = xi + h;
    const int first = static_cast<int>(std::floor(clamp_to_grid(a, cells)));
    const double inv_l = 1.0 / (2.0 * h);  // 1 / l_p in cell units
    for (int k = 0; k < width; ++k) {
      const int i = first + k;
      const std::size_t e = q * width + k;
      // Nodes outside the grid (beyond the ghost layer too) take no weight.
      const int ic = std::clamp(i, -Grid<1>::ghost, cells + Grid<1>::ghost);
      st.node[e] = static_cast<int>(g.index1(ic));
      if (i < 0 || i > cells) continue;
      const double sa = hat_ext(a, i, cells), sb = hat_ext(b, i, cells);
      st.S[e] = integrate ? (hat_ext_integral(b, i, cells) - hat_ext_integral(a, i, cells)) * inv_l
                          : 0.5 * (sa + sb);
      st.G[0][e] = (sb - sa) * inv_l * inv;
    }
  }
}

}  // namespace mpmx::mpm::shape
