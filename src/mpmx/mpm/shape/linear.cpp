// Original MPM: linear hat functions and their piecewise-constant gradient (eqs. 3.9, 4.1).
#include "mpmx/mpm/shape/linear.hpp"

#include <algorithm>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

void evaluate_linear(const Grid<1>& g, const Particles<1>& p, Stencil<1>& st) {
  const std::size_t n = p.size();
  st.reset(n, 2, false);
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const int cells = g.cells[0];
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (p.x[0][q] - x0) * inv;
    require_inside(xi, cells, q, p.x[0][q]);
    const double xc = clamp_to_grid(xi, cells);
    const int c = std::min(static_cast<int>(xc), cells - 1);  // xc >= 0: truncation is floor
    const double f = xc - c;
    const std::size_t k = 2 * q;
    st.node[k] = static_cast<int>(g.index1(c));
    st.node[k + 1] = static_cast<int>(g.index1(c + 1));
    st.S[k] = 1.0 - f;
    st.S[k + 1] = f;
    // Flat continuation past the ends has no gradient.
    const double g = (xi >= 0.0 && xi <= cells) ? inv : 0.0;
    st.G[0][k] = -g;
    st.G[0][k + 1] = g;
  }
}

}  // namespace mpmx::mpm::shape
