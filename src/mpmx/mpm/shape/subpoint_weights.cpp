// DDMP weights averaged over each particle's sub-points (eqs. 3.31, 6.1-6.3): the cost of
// `ddmp_subpoints` is almost all here, one alpha (eq. 3.27) per sub-point per step.
//
// A particle's evenly spaced sub-points lie in its cell c and at most one neighbour
// (all but a few), or not. The first kind go a vector of particles at a time, every
// sub-point in registers: sums of alpha, alpha f and f over the sub-points, in all and
// in the neighbour, give the three weights of each cell, as <(1-alpha) f> =
// <f> - <alpha f> and <(1-alpha)(1-f)> = <1> - <alpha> - <(1-alpha) f>. The rest
// (past a grid end, three cells or further) go point by point as the stencil path's
// evaluate_ddmp_subpoints.

#include <algorithm>

#include "mpmx/mpm/shape/linear_fused_detail.hpp"
#include "mpmx/mpm/shape/simd.hpp"

namespace mpmx::mpm::shape::fused {

namespace {

using simd::fmadd;
using simd::kLanes;
using simd::splat;
using simd::vdouble;

// Where a vector of particles' sub-points start (in cell units, relative to the cell c)
// and how far apart they are, as sub_h and sub_step but with the constant factors taken
// first (no divide per vector; the points move by an ulp or so).
struct Spread {
  vdouble c, lo, step;
};
struct SpreadScale {
  double h, step;  // half width and spacing per unit length
  SpreadScale(double inv, int ns)
      : h(0.5 * inv * (1.0 - 1.0 / ns)), step(ns > 1 ? 2.0 * h / (ns - 1) : 0.0) {}
};
[[gnu::always_inline]] inline Spread spread(const double* x, const double* len, const int* cell,
                                            double x0, double inv, const SpreadScale& k) {
  const vdouble xi = (simd::load(x) - x0) * inv, l = simd::load(len);
  return {simd::load_cells(cell), xi - k.h * l, k.step * l};
}

// The weights of a vector of particles: W0..2 = <alpha> in c, <(1-alpha) S> at nodes c
// and c+1; X0..3 = <alpha> in c-1 and c+1, <(1-alpha) S> at nodes c-1 and c+2. `side`
// (-1 or +1) is the neighbour cell a particle's sub-points may reach.
struct Weights {
  vdouble w[3], x[4];
};
// V vectors of particles at once: alpha is a long chain of dependent operations, and the
// core overlaps the chains of different vectors only when they are close in the loop.
template <int V>
[[gnu::always_inline]] inline void weights(const Spread* s, const vdouble* side, int ns, Weights* o) {
  const vdouble zero{}, one = splat(1.0);
  vdouble f0[V], A[V], AF[V], F[V], An[V], AFn[V], Fn[V], Nn[V];
  for (int v = 0; v < V; ++v) {
    f0[v] = s[v].lo - s[v].c;
    A[v] = AF[v] = F[v] = An[v] = AFn[v] = Fn[v] = Nn[v] = zero;
  }
  vdouble kv{};
  for (int k = 0; k < ns; ++k, kv += 1.0) {
    for (int v = 0; v < V; ++v) {
      const vdouble fc = fmadd(kv, s[v].step, f0[v]);  // fraction in the particle's cell
      const auto out = (fc < 0.0) | (fc >= 1.0);
      const vdouble f = out ? fc - side[v] : fc;  // in the sub-point's own cell
      const vdouble al = simd::alpha_of_t(f - f * f), alf = al * f;
      A[v] += al, AF[v] += alf, F[v] += f;
      An[v] += out ? al : zero;
      AFn[v] += out ? alf : zero;
      Fn[v] += out ? f : zero;
      Nn[v] += out ? one : zero;
    }
  }
  const double w = 1.0 / ns;
  for (int v = 0; v < V; ++v) {
    // In c (z) and in the neighbour (n): <alpha>, <(1-alpha)(1-f)>, <(1-alpha) f>.
    const vdouble Az = A[v] - An[v], AFz = AF[v] - AFn[v], Fz = F[v] - Fn[v];
    const vdouble Nz = static_cast<double>(ns) - Nn[v];
    const vdouble bz1 = (Fz - AFz) * w, bz0 = (Nz - Az) * w - bz1;
    const vdouble bn1 = (Fn[v] - AFn[v]) * w, bn0 = (Nn[v] - An[v]) * w - bn1, an = An[v] * w;
    const auto left = side[v] < 0.0;
    o[v].w[0] = Az * w;
    o[v].w[1] = bz0 + (left ? bn1 : zero);  // cell c-1's right node is c
    o[v].w[2] = bz1 + (left ? zero : bn0);  // cell c+1's left node is c+1
    o[v].x[0] = left ? an : zero, o[v].x[1] = left ? zero : an;
    o[v].x[2] = left ? bn0 : zero, o[v].x[3] = left ? zero : bn1;
  }
}

// Point by point, as evaluate_ddmp_subpoints: the particles of `ids` (positions k in the
// mixed list, whose weights go to Wx[4 k ..]). Returns whether any has a sub-point more
// than a cell away.
int general_weights(const std::vector<int>& ids, const std::vector<int>& mixed,
                    const double* __restrict x, const double* __restrict len,
                    const int* __restrict cell, double x0, double inv, double top, int ns,
                    std::size_t n, double* __restrict W, int* __restrict far, double* __restrict Wx) {
  const double w = 1.0 / ns;
  int any = 0;
  for (const int k : ids) {
    const std::size_t q = static_cast<std::size_t>(mixed[static_cast<std::size_t>(k)]);
    const double xi = (x[q] - x0) * inv;
    const double h = sub_h(len[q], inv, ns), step = sub_step(h, ns);
    double acc[7] = {};
    int out = 0;
    for (int sp = 0; sp < ns; ++sp) {
      const SubWeights sw = sub_weights(xi - h + sp * step, top);
      const int d = sw.c - cell[q];
      out |= d < -1 || d > 1;
      if (d == -1) acc[0] += sw.a, acc[3] += sw.b0, acc[4] += sw.b1;
      if (d == 0) acc[1] += sw.a, acc[4] += sw.b0, acc[5] += sw.b1;
      if (d == 1) acc[2] += sw.a, acc[5] += sw.b0, acc[6] += sw.b1;
    }
    W[q] = acc[1] * w, W[n + q] = acc[4] * w, W[2 * n + q] = acc[5] * w;
    double* wx = Wx + 4 * k;
    wx[0] = acc[0] * w, wx[1] = acc[2] * w, wx[2] = acc[3] * w, wx[3] = acc[6] * w;
    far[q] = out;
    any |= out;
  }
  return any;
}

}  // namespace

int subpoint_weights(std::size_t n, const double* __restrict x, const double* __restrict len,
                     const int* __restrict cell, double x0, double inv, double top, int ns,
                     double* __restrict W, int* __restrict far, std::vector<int>& mixed,
                     std::vector<double>& Wx) {
  constexpr int V = 2, K = V * kLanes;  // particles per block
  const SpreadScale scale(inv, ns);
  mixed.clear();
  Wx.clear();
  std::fill(far, far + n, 0);
  thread_local std::vector<int> rest;  // positions in `mixed` for general_weights
  rest.clear();
  for (std::size_t q = 0; q < n; q += K) {
    // The last block from a padded copy.
    const std::size_t m = std::min<std::size_t>(K, n - q);
    const bool full = m == static_cast<std::size_t>(K);
    alignas(64) double xs[K], ls[K], w[3][K];
    alignas(64) int cs[K];
    const double *px = x + q, *pl = len + q;
    const int* pc = cell + q;
    if (!full) {
      for (int j = 0; j < K; ++j) {
        const std::size_t r = q + std::min<std::size_t>(j, m - 1);
        xs[j] = x[r], ls[j] = len[r], cs[j] = cell[r];
      }
      px = xs, pl = ls, pc = cs;
    }
    Spread s[V];
    vdouble side[V];
    Weights o[V];
    for (int v = 0; v < V; ++v) {
      s[v] = spread(px + v * kLanes, pl + v * kLanes, pc + v * kLanes, x0, inv, scale);
      side[v] = s[v].lo < s[v].c ? splat(-1.0) : splat(1.0);
    }
    weights<V>(s, side, ns, o);
    for (int v = 0; v < V; ++v) {
      const int at = v * kLanes;
      double* w0 = full ? W + q + at : w[0] + at;
      double* w1 = full ? W + n + q + at : w[1] + at;
      double* w2 = full ? W + 2 * n + q + at : w[2] + at;
      simd::store(w0, o[v].w[0]), simd::store(w1, o[v].w[1]), simd::store(w2, o[v].w[2]);
      // Particles with sub-points outside c: listed with their neighbour weights, and
      // those not in c and one neighbour inside the grid again for general_weights.
      const vdouble lo = s[v].lo, hi = lo + (ns - 1) * s[v].step, c = s[v].c;
      const unsigned lanes = (1u << std::min<std::size_t>(kLanes, m - std::min<std::size_t>(m, at))) - 1;
      const unsigned other = ~simd::bits((lo >= c) & (hi < c + 1.0)) & lanes;
      if (!other) continue;
      const unsigned two = simd::bits((lo >= simd::max(c - 1.0, vdouble{})) & (hi < c + 2.0) &
                                      (hi < top)) &
                           ~(simd::bits(lo < c) & simd::bits(hi >= c + 1.0));
      alignas(64) double wx[4][kLanes];
      for (int i = 0; i < 4; ++i) simd::store(wx[i], o[v].x[i]);
      for (unsigned b = other; b; b &= b - 1) {
        const int j = __builtin_ctz(b);
        if (!(two >> j & 1)) rest.push_back(static_cast<int>(mixed.size()));
        mixed.push_back(static_cast<int>(q + at + j));
        for (int i = 0; i < 4; ++i) Wx.push_back(wx[i][j]);
      }
    }
    if (!full) {
      std::copy(w[0], w[0] + m, W + q);
      std::copy(w[1], w[1] + m, W + n + q);
      std::copy(w[2], w[2] + m, W + 2 * n + q);
    }
  }
  return general_weights(rest, mixed, x, len, cell, x0, inv, top, ns, n, W, far, Wx.data());
}

}  // namespace mpmx::mpm::shape::fused
