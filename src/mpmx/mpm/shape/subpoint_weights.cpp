// DDMP weights averaged over each particle's sub-points (eqs. 3.31, 6.1-6.3): the cost of
// `ddmp_subpoints` is almost all here, one alpha (eq. 3.27) per sub-point per step.
//
// The particles are sorted by where their evenly spaced sub-points lie: all in the
// particle's cell c (most of them), in c and one neighbour inside the grid, or neither.
// The first two kinds go a vector of particles at a time, every sub-point in registers:
// sums of alpha, alpha f and f (per cell for the second kind) give the three weights of
// a cell, as <(1-alpha) f> = <f> - <alpha f> and <(1-alpha)(1-f)> = <1> - <alpha> -
// <(1-alpha) f>. The rest (past a grid end, three cells or further) go point by point
// as the stencil path's evaluate_ddmp_subpoints.

#include <algorithm>
#include <array>
#include <utility>

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
  SpreadScale(double inv, int ns) : h(sub_h(1.0, inv, ns)), step(sub_step(h, ns)) {}
};
[[gnu::always_inline]] inline Spread spread(const double* x, const double* len, const int* cell,
                                            double x0, double inv, const SpreadScale& k) {
  const vdouble xi = (simd::load(x) - x0) * inv, l = simd::load(len);
  return {simd::load_cells(cell), xi - k.h * l, k.step * l};
}

// Particles with every sub-point in their cell: the sums of alpha and alpha f only (the
// sum of f is n times the particle's own fraction: the points are centred on it), so
// W = <alpha>, 1 - <alpha> - <(1-alpha) f>, <f> - <alpha f>.
struct OwnSums {
  vdouble w0, w1, w2;
};
template <int V>
[[gnu::always_inline]] inline void own_sums(const Spread* s, int ns, OwnSums* o) {
  vdouble f0[V], A[V], AF[V];
  for (int v = 0; v < V; ++v) f0[v] = s[v].lo - s[v].c, A[v] = AF[v] = vdouble{};
  vdouble kv{};
  for (int k = 0; k < ns; ++k, kv += 1.0) {
    for (int v = 0; v < V; ++v) {
      const vdouble f = fmadd(kv, s[v].step, f0[v]);
      const vdouble al = simd::alpha(f);
      A[v] += al;
      AF[v] = fmadd(al, f, AF[v]);
    }
  }
  const double w = 1.0 / ns;
  for (int v = 0; v < V; ++v) {
    // The mean of the fractions is the particle's own (the points are centred on it).
    const vdouble a = A[v] * w, bf = (s[v].lo + 0.5 * (ns - 1) * s[v].step - s[v].c) - AF[v] * w;
    o[v] = {a, 1.0 - a - bf, bf};
  }
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
      const vdouble al = simd::alpha(f), alf = al * f;
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
  std::fill(far, far + n, 0);
  // Which particles keep their sub-points in their cell (`own`), reach one neighbour
  // inside the grid (`two`), or neither (`rest`): a vector at a time. The mixed ones are
  // listed in `mixed` (two and rest are positions in it).
  thread_local std::vector<int> own_tls, two_tls, rest_tls;
  std::vector<int>&own = own_tls, &two = two_tls, &rest = rest_tls;  // one TLS lookup
  own.clear(), two.clear(), rest.clear();
  for (std::size_t q = 0; q < n; q += kLanes) {
    const std::size_t m = std::min<std::size_t>(kLanes, n - q);
    alignas(64) double xs[kLanes], ls[kLanes];
    alignas(64) int cs[kLanes];
    const double *px = x + q, *pl = len + q;
    const int* pc = cell + q;
    if (m < static_cast<std::size_t>(kLanes)) {  // the last block from a padded copy
      for (int j = 0; j < kLanes; ++j) {
        const std::size_t r = q + std::min<std::size_t>(j, m - 1);
        xs[j] = x[r], ls[j] = len[r], cs[j] = cell[r];
      }
      px = xs, pl = ls, pc = cs;
    }
    const Spread sp = spread(px, pl, pc, x0, inv, scale);
    const vdouble lo = sp.lo, hi = lo + (ns - 1) * sp.step, c = sp.c;
    const unsigned mine = simd::bits((lo >= c) & (hi < c + 1.0));
    const unsigned in_two = simd::bits((lo >= simd::max(c - 1.0, vdouble{})) & (hi < c + 2.0) & (hi < top)) &
                            ~(simd::bits(lo < c) & simd::bits(hi >= c + 1.0));
    for (std::size_t j = 0; j < m; ++j) {
      const int id = static_cast<int>(q + j);
      if (mine >> j & 1) {
        own.push_back(id);
      } else {
        (in_two >> j & 1 ? two : rest).push_back(static_cast<int>(mixed.size()));
        mixed.push_back(id);
      }
    }
  }
  Wx.assign(4 * mixed.size(), 0.0);
  // K particles of a list at a time, copied together (the last block padded).
  alignas(64) double xs[K], ls[K];
  alignas(64) int cs[K];
  auto stage = [&](const std::vector<int>& list, std::size_t b, const std::vector<int>* via) {
    const std::size_t m = std::min<std::size_t>(K, list.size() - b);
    for (int j = 0; j < K; ++j) {
      const int at = list[b + std::min<std::size_t>(j, m - 1)];
      const std::size_t q = static_cast<std::size_t>(via ? (*via)[static_cast<std::size_t>(at)] : at);
      xs[j] = x[q], ls[j] = len[q], cs[j] = cell[q];
    }
    Spread s[V];
    for (int v = 0; v < V; ++v) s[v] = spread(xs + v * kLanes, ls + v * kLanes, cs + v * kLanes, x0, inv, scale);
    return std::pair{m, std::to_array(s)};
  };
  for (std::size_t b = 0; b < own.size(); b += K) {
    const auto [m, s] = stage(own, b, nullptr);
    OwnSums o[V];
    own_sums<V>(s.data(), ns, o);
    alignas(64) double w[3][K];
    for (int v = 0; v < V; ++v) {
      simd::store(w[0] + v * kLanes, o[v].w0);
      simd::store(w[1] + v * kLanes, o[v].w1);
      simd::store(w[2] + v * kLanes, o[v].w2);
    }
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t q = static_cast<std::size_t>(own[b + j]);
      W[q] = w[0][j], W[n + q] = w[1][j], W[2 * n + q] = w[2][j];
    }
  }
  for (std::size_t b = 0; b < two.size(); b += K) {
    const auto [m, s] = stage(two, b, &mixed);
    vdouble side[V];
    Weights o[V];
    for (int v = 0; v < V; ++v) side[v] = s[v].lo < s[v].c ? splat(-1.0) : splat(1.0);
    weights<V>(s.data(), side, ns, o);
    alignas(64) double w[3][K], wx[4][K];
    for (int v = 0; v < V; ++v) {
      for (int i = 0; i < 3; ++i) simd::store(w[i] + v * kLanes, o[v].w[i]);
      for (int i = 0; i < 4; ++i) simd::store(wx[i] + v * kLanes, o[v].x[i]);
    }
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t k = static_cast<std::size_t>(two[b + j]);
      const std::size_t q = static_cast<std::size_t>(mixed[k]);
      W[q] = w[0][j], W[n + q] = w[1][j], W[2 * n + q] = w[2][j];
      for (int i = 0; i < 4; ++i) Wx[4 * k + i] = wx[i][j];
    }
  }
  return general_weights(rest, mixed, x, len, cell, x0, inv, top, ns, n, W, far, Wx.data());
}

}  // namespace mpmx::mpm::shape::fused
