// DDMP weights averaged over each particle's sub-points (eqs. 3.31, 6.1-6.3): the cost of
// `ddmp_subpoints` is almost all here, one alpha (eq. 3.27) per sub-point per step.
//
// The particles go in their order, a block of vectors at a time, every sub-point in
// registers; a particle's evenly spaced sub-points lie in its cell c or reach one
// neighbour. Sums of alpha, alpha f and f per cell give the three weights of a cell, as
// <(1-alpha) f> = <f> - <alpha f> and <(1-alpha)(1-f)> = <1> - <alpha> - <(1-alpha) f>.
// Particles whose sub-points lie past a grid end or over three cells (rare) are redone
// point by point as the stencil path's evaluate_ddmp_subpoints. Compiled once per vector
// path (hwy/foreach_target.h includes this file again for each); every lane is one
// particle, so the results do not depend on the width.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the paths to compile
// clang-format on

#include <algorithm>
#include <array>
#include <utility>

#include "mpmx/mpm/fused1d/linear_fused_detail.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "mpmx/mpm/fused1d/subpoint_weights.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "mpmx/mpm/fused1d/simd.hpp"

HWY_BEFORE_NAMESPACE();
namespace mpmx::mpm::shape::HWY_NAMESPACE {

using namespace fused;

namespace {

namespace hn = hwy::HWY_NAMESPACE;
using simd::fmadd;
using D = simd::DFull;
using vdouble = hn::Vec<D>;
using vmask = hn::Mask<D>;
constexpr int kLanes = simd::kLanes<D>;
HWY_INLINE vdouble splat(double a) { return hn::Set(D(), a); }

// Where a vector of particles' sub-points start and how far apart they are, in cell units
// (c the particles' cells), as sub_h and sub_step but with the constant factors taken first
// (no divide per vector; the points move by an ulp or so).
struct Spread {
  vdouble c, lo, step;
};
struct SpreadScale {
  double h, step;  // half width and spacing per unit length
  SpreadScale(double inv, int ns) : h(sub_h(1.0, inv, ns)), step(sub_step(h, ns)) {}
};
[[gnu::always_inline]] inline Spread spread(const double* x, const double* len, const int* cell,
                                            double x0, double inv, const SpreadScale& k) {
  const D d;
  const vdouble xi = (simd::load(d, x) - splat(x0)) * splat(inv), l = simd::load(d, len);
  return {simd::load_cells_as_double(d, cell), xi - splat(k.h) * l, splat(k.step) * l};
}

// The weights of a vector of particles: W0..2 = <alpha> in c, <(1-alpha) S> at nodes c
// and c+1; X0..3 = <alpha> in c-1 and c+1, <(1-alpha) S> at nodes c-1 and c+2. `left`:
// the lanes whose sub-points may reach cell c-1 (the others may reach c+1); `reach`: the
// lanes whose sub-points leave c at all.
//
// A particle's sub-points lie on three nodes at most, 0, 1, 2 in a frame u that puts the
// first one at node 0 (u = f + 1 where they reach c-1, u = f otherwise). The three node
// weights w_j = sum (1 - alpha) S_j(u) follow from their moments: sum_j w_j = sum (1 -
// alpha), sum_j j w_j = sum (1 - alpha) u and sum_j j^2 w_j = sum (1 - alpha)(u^2 + t),
// t = f (1 - f), since hats reproduce lines exactly and interpolate u^2 to u^2 + t. So
// each sub-point costs its alpha and five sums, with no per-point select.
struct Weights {
  vdouble w[3], x[4];
};
// V vectors of particles at once: alpha is a long chain of dependent operations, and the
// core overlaps the chains of different vectors only when they are close in the loop.
template <int V>
[[gnu::always_inline]] inline void weights(const Spread* s, const vmask* left, const vmask* reach, int ns,
                                           Weights* o) {
  const vdouble zero = hn::Zero(D()), one = splat(1.0);
  vdouble u0[V], A[V], AU[V], AL[V], AQ[V], Q[V];
  for (int v = 0; v < V; ++v) {
    u0[v] = s[v].lo - s[v].c + hn::IfThenElseZero(left[v], one);
    A[v] = AU[v] = AL[v] = AQ[v] = Q[v] = zero;
  }
  vdouble kv = zero;
  for (int k = 0; k < ns; ++k, kv += one) {
    for (int v = 0; v < V; ++v) {
      const vdouble u = fmadd(kv, s[v].step, u0[v]);
      const vdouble node = hn::IfThenElseZero(hn::Ge(u, one), one);  // the sub-point's cell in the frame
      const vdouble f = u - node, t = f * (one - f), al = simd::alpha(f), q = fmadd(u, u, t);
      A[v] += al;
      AU[v] = fmadd(al, u, AU[v]);
      AL[v] = fmadd(al, node, AL[v]);
      AQ[v] = fmadd(al, q, AQ[v]);
      Q[v] += q;
    }
  }
  const double w = 1.0 / ns, mid = 0.5 * (ns - 1);
  for (int v = 0; v < V; ++v) {
    const vdouble vns = splat(static_cast<double>(ns)), vw = splat(w);
    const vdouble U = vns * fmadd(splat(mid), s[v].step, u0[v]);  // sum of u
    const vdouble M0 = vns - A[v], M1 = U - AU[v], M2 = Q[v] - AQ[v];
    const vdouble w2 = hn::IfThenElseZero(reach[v], splat(0.5) * (M2 - M1));  // zero, not round-off, for one cell
    const vdouble w1 = M1 - splat(2.0) * w2, w0 = M0 - w1 - w2;
    const vmask l = left[v];
    const vdouble in_c = hn::IfThenElse(l, AL[v], A[v] - AL[v]) * vw, in_n = (A[v] * vw - in_c);
    o[v].w[0] = in_c;
    o[v].w[1] = hn::IfThenElse(l, w1, w0) * vw;
    o[v].w[2] = hn::IfThenElse(l, w2, w1) * vw;
    o[v].x[0] = hn::IfThenElseZero(l, in_n), o[v].x[1] = hn::IfThenZeroElse(l, in_n);
    o[v].x[2] = hn::IfThenElseZero(l, w0 * vw), o[v].x[3] = hn::IfThenZeroElse(l, w2 * vw);
  }
}

// Point by point, as evaluate_ddmp_subpoints: particle q's weights (W and Wx at q, n apart).
// Returns whether it has a sub-point more than a cell away.
int point_weights(std::size_t q, const double* __restrict x, const double* __restrict len,
                  const int* __restrict cell, double x0, double inv, double top, int ns,
                  std::size_t n, double* __restrict W, double* __restrict Wx) {
  const double w = 1.0 / ns;
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
  Wx[q] = acc[0] * w, Wx[n + q] = acc[2] * w, Wx[2 * n + q] = acc[3] * w, Wx[3 * n + q] = acc[6] * w;
  return out;
}

}  // namespace

void subpoint_weights_kernel(std::size_t n, const double* __restrict x, const double* __restrict len,
                      const int* __restrict cell, double x0, double inv, double top, int ns,
                      double* __restrict W, double* __restrict Wx, std::vector<int>& mixed,
                      std::vector<int>& stray) {
  constexpr int V = 2, K = V * kLanes;  // particles per block
  const SpreadScale scale(inv, ns);
  // The mixed list is compacted in a scratch that only grows (a resize would zero-fill).
  thread_local std::vector<int> listed;
  if (listed.size() < n) listed.resize(n);
  stray.clear();
  std::size_t n_mixed = 0;
  // K particles from q on, read from (px, pl, pc) (the particles' arrays at q, or a padded
  // copy of the last block), results stored for the first m.
  auto block = [&](std::size_t q, std::size_t m, const double* px, const double* pl, const int* pc) {
    const D d;
    Spread s[V];
    vmask left[V], reach[V];
    unsigned out = 0, odd = 0;  // lanes with sub-points in a neighbour cell / elsewhere
    for (int v = 0; v < V; ++v) {
      s[v] = spread(px + v * kLanes, pl + v * kLanes, pc + v * kLanes, x0, inv, scale);
      const vdouble lo = s[v].lo, hi = lo + splat(ns - 1) * s[v].step, c = s[v].c;
      left[v] = hn::Lt(lo, c);
      const vmask right = hn::Ge(hi, c + splat(1.0));
      reach[v] = hn::Or(left[v], right);
      // One neighbour at most, inside the grid: the vector kernel's case.
      const vmask two = hn::AndNot(hn::And(left[v], right),
                                   hn::And(hn::And(hn::Ge(lo, hn::Max(c - splat(1.0), hn::Zero(d))),
                                                   hn::Lt(hi, c + splat(2.0))),
                                           hn::Lt(hi, splat(top))));
      out |= simd::bits(d, reach[v]) << (v * kLanes);
      odd |= simd::bits(d, hn::Not(two)) << (v * kLanes);
    }
    Weights o[V];
    weights<V>(s, left, reach, ns, o);
    if (m == K) {
      for (int i = 0; i < 3; ++i)
        for (int v = 0; v < V; ++v) simd::store(W + i * n + q + v * kLanes, o[v].w[i]);
      for (int i = 0; i < 4; ++i)
        for (int v = 0; v < V; ++v) simd::store(Wx + i * n + q + v * kLanes, o[v].x[i]);
    } else {
      double w[7][K];
      for (int v = 0; v < V; ++v) {
        for (int i = 0; i < 3; ++i) simd::store(w[i] + v * kLanes, o[v].w[i]);
        for (int i = 0; i < 4; ++i) simd::store(w[3 + i] + v * kLanes, o[v].x[i]);
      }
      for (std::size_t j = 0; j < m; ++j) {
        for (int i = 0; i < 3; ++i) W[i * n + q + j] = w[i][j];
        for (int i = 0; i < 4; ++i) Wx[i * n + q + j] = w[3 + i][j];
      }
    }
    // Lanes the kernel does not cover, point by point (rare: past a grid end, or three cells).
    for (unsigned b = odd & ((1u << m) - 1); b; b &= b - 1) {
      const std::size_t r = q + static_cast<std::size_t>(__builtin_ctz(b));
      if (point_weights(r, x, len, cell, x0, inv, top, ns, n, W, Wx)) stray.push_back(static_cast<int>(r));
    }
    // The mixed list without a branch per particle: every lane is written, kept if it reaches.
    const unsigned keep = out | odd;
    for (std::size_t j = 0; j < m; ++j) {
      listed[n_mixed] = static_cast<int>(q + j);
      n_mixed += keep >> j & 1;
    }
  };
  std::size_t q = 0;
  for (; q + K <= n; q += K) block(q, K, x + q, len + q, cell + q);
  if (q < n) {  // the last block from a padded copy
    const std::size_t m = n - q;
    double xs[K], ls[K];
    int cs[K];
    for (int j = 0; j < K; ++j) {
      const std::size_t r = q + std::min<std::size_t>(j, m - 1);
      xs[j] = x[r], ls[j] = len[r], cs[j] = cell[r];
    }
    block(q, m, xs, ls, cs);
  }
  mixed.assign(listed.begin(), listed.begin() + static_cast<std::ptrdiff_t>(n_mixed));
}

}  // namespace mpmx::mpm::shape::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::mpm::shape::fused {

HWY_EXPORT(subpoint_weights_kernel);

void subpoint_weights(std::size_t n, const double* __restrict x, const double* __restrict len,
                      const int* __restrict cell, double x0, double inv, double top, int ns,
                      double* __restrict W, double* __restrict Wx, std::vector<int>& mixed,
                      std::vector<int>& stray) {
  HWY_DYNAMIC_DISPATCH(subpoint_weights_kernel)(n, x, len, cell, x0, inv, top, ns, W, Wx, mixed, stray);
}

}  // namespace mpmx::mpm::shape::fused
#endif  // HWY_ONCE
