#include "mpmx/mpm/shape/linear_fused.hpp"

#include <algorithm>

#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

void p2g_linear(const Grid<1>&, const Particles<1>& p, bool reference_volume, LinearCells& lc,
                Grid<1>& g) {
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  lc.cell.resize(n);
  lc.frac.resize(n);
  lc.grad.resize(n);
  const std::size_t stride = static_cast<std::size_t>(cells);
  lc.sums.assign(5 * stride, 0.0);
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const double* __restrict x = p.x[0].data();
  const double* __restrict v = p.v[0].data();
  const double* __restrict m = p.mass.data();
  const double* __restrict vol = reference_volume ? p.volume0.data() : p.volume.data();
  const double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  int* __restrict cell = lc.cell.data();
  double* __restrict frac = lc.frac.data();
  double* __restrict grad = lc.grad.data();

  // Pass 1 (vectorises): cell, fraction and gradient of every particle, and whether the
  // particles still lie in cell order (in 1-D they keep their order unless they cross).
  const double top = static_cast<double>(cells), last = top - 1.0;
  long outside = 0;
  int unordered = 0;
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (x[q] - x0) * inv;
    outside += !(xi >= -1.0 && xi <= top + 1.0);
    const double xc = xi < 0.0 ? 0.0 : (xi > top ? top : xi);
    const double cf = static_cast<double>(static_cast<int>(xc));  // xc >= 0: floor
    const double cc = cf > last ? last : cf;
    cell[q] = static_cast<int>(cc);
    frac[q] = xc - cc;
    grad[q] = (xi >= 0.0 && xi <= top) ? inv : 0.0;
  }
  if (outside)
    for (std::size_t q = 0; q < n; ++q) require_inside((x[q] - x0) * inv, cells, q, x[q]);
  for (std::size_t q = 1; q < n; ++q) unordered |= cell[q] < cell[q - 1];

  // Pass 2: per-cell sums. In cell order, a running sum restarted at each new cell and
  // stored after every particle leaves each cell's total in place without a branch;
  // otherwise plain accumulation.
  double* __restrict S0 = lc.sums.data();
  double* __restrict S1 = S0 + stride;
  double* __restrict S2 = S1 + stride;
  double* __restrict S3 = S2 + stride;
  double* __restrict S4 = S3 + stride;
  if (!unordered) {
    double a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0;
    int prev = -1;
    for (std::size_t q = 0; q < n; ++q) {
      const int c = cell[q];
      const double keep = c == prev ? 1.0 : 0.0;
      const double mf = m[q] * frac[q], mv = m[q] * v[q];
      a0 = a0 * keep + m[q];
      a1 = a1 * keep + mf;
      a2 = a2 * keep + mv;
      a3 = a3 * keep + mv * frac[q];
      a4 = a4 * keep + vol[q] * (sig[q] - qv[q]) * grad[q];
      S0[c] = a0, S1[c] = a1, S2[c] = a2, S3[c] = a3, S4[c] = a4;
      prev = c;
    }
  } else {
    for (std::size_t q = 0; q < n; ++q) {
      const int c = cell[q];
      const double mf = m[q] * frac[q], mv = m[q] * v[q];
      S0[c] += m[q], S1[c] += mf, S2[c] += mv, S3[c] += mv * frac[q];
      S4[c] += vol[q] * (sig[q] - qv[q]) * grad[q];
    }
  }

  // Pass 3: nodes. Node i takes (sum m - sum m f) of cell i and sum m f of cell i-1;
  // the force is +V sigma/dx from cell i and -V sigma/dx from cell i-1 (G = -1/dx, +1/dx).
  std::fill(g.mass.begin(), g.mass.end(), 0.0);
  std::fill(g.momentum[0].begin(), g.momentum[0].end(), 0.0);
  std::fill(g.force[0].begin(), g.force[0].end(), 0.0);
  double* __restrict M = g.mass.data() + Grid<1>::ghost;
  double* __restrict P = g.momentum[0].data() + Grid<1>::ghost;
  double* __restrict F = g.force[0].data() + Grid<1>::ghost;
  for (int c = 0; c < cells; ++c) {
    M[c] += S0[c] - S1[c];
    M[c + 1] += S1[c];
    P[c] += S2[c] - S3[c];
    P[c + 1] += S3[c];
    F[c] += S4[c];
    F[c + 1] -= S4[c];
  }
}

double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                  Particles<1>& p) {
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  const double* __restrict VL = g.velocity_L[0].data() + Grid<1>::ghost;
  const double* __restrict VN = g.velocity[0].data() + Grid<1>::ghost;
  lc.d0.resize(cells);
  lc.dd.resize(cells);
  lc.g0.resize(cells);
  lc.dg.resize(cells);
  double* __restrict d0 = lc.d0.data();
  double* __restrict dd = lc.dd.data();
  double* __restrict g0 = lc.g0.data();
  double* __restrict dg = lc.dg.data();
  for (int c = 0; c < cells; ++c) {
    const double a = VL[c] - VN[c], b = VL[c + 1] - VN[c + 1];
    const double u = wl * VL[c] + wn * VN[c], w = wl * VL[c + 1] + wn * VN[c + 1];
    d0[c] = a, dd[c] = b - a, g0[c] = u, dg[c] = w - u;
  }
  const int* __restrict cell = lc.cell.data();
  const double* __restrict frac = lc.frac.data();
  const double* __restrict grad = lc.grad.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  const double dtm = move ? dt : 0.0;
  double check = 0.0;
  for (std::size_t q = 0; q < n; ++q) {
    const int c = cell[q];
    const double f = frac[q];
    v[q] += d0[c] + f * dd[c];
    x[q] += dtm * (g0[c] + f * dg[c]);
    L[q] = dg[c] * grad[q];
    check += v[q] + x[q];
  }
  return check;
}

}  // namespace mpmx::mpm::shape
