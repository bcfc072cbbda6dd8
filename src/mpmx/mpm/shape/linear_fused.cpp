#include "mpmx/mpm/shape/linear_fused.hpp"

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

namespace {

// Cell (clamped to the grid, eq. 3.9: the flat continuation past the ends) and fraction
// of a point at xi in cell units, as locate(clamp_to_grid(xi)) but free of int round
// trips so that loops over it vectorise. xc >= 0: truncation is floor.
struct Cell {
  double c, f;
};
inline Cell cell_of(double xi, double top) {
  const double xc = std::min(std::max(xi, 0.0), top);
  const double cc = std::min(static_cast<double>(static_cast<int>(xc)), top - 1.0);
  return {cc, xc - cc};
}

// alpha of eq. 3.27 (as ddmp_alpha); q >= 0 always, so sqrt needs no errno path.
inline double alpha(double f) {
  const double q = 4.0 * f * (1.0 - f);
  return 0.5 * q * __builtin_sqrt(q);
}

// Pass 1 kernel (vectorises): cell, fraction and gradient of every particle; returns
// whether any lies more than a cell past the grid, and in `edge` whether any lies past
// its ends at all (a zero gradient there).
[[gnu::noinline]] int locate_kernel(std::size_t n, const double* __restrict x, double x0, double inv, double top,
                  int* __restrict cell, double* __restrict frac, double* __restrict grad, int& edge) {
  int outside = 0, past = 0;
#pragma omp simd reduction(| : outside, past)
  for (std::size_t q = 0; q < n; ++q) {
    const double xi = (x[q] - x0) * inv;
    outside |= !(xi >= -1.0) | !(xi <= top + 1.0);  // `|`, not `||`: no branch
    const bool in = (xi >= 0.0) & (xi <= top);
    past |= !in;
    const Cell cf = cell_of(xi, top);
    cell[q] = static_cast<int>(cf.c);
    frac[q] = cf.f;
    grad[q] = in ? inv : 0.0;
  }
  edge = past;
  return outside;
}

// Pass 1: locate every particle (stops the run for one off the grid). Returns whether
// the particles still lie in cell order (in 1-D they keep it unless they cross).
bool locate_all(const Grid<1>& g, const Particles<1>& p, LinearCells& lc) {
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  lc.cell.resize(n + 1);
  lc.cell[n] = -1;  // a sentinel: no particle's cell
  lc.frac.resize(n);
  lc.grad.resize(n);
  const double x0 = g.lower[0], inv = g.inv_dx[0];
  const double* x = p.x[0].data();
  int edge = 0;
  if (locate_kernel(n, x, x0, inv, cells, lc.cell.data(), lc.frac.data(), lc.grad.data(), edge))
    for (std::size_t q = 0; q < n; ++q) require_inside((x[q] - x0) * inv, cells, q, x[q]);
  const int* __restrict cell = lc.cell.data();
  int unordered = 0;
#pragma omp simd reduction(| : unordered)
  for (std::size_t q = 1; q < n; ++q) unordered |= cell[q] < cell[q - 1];
  lc.ordered = !unordered;
  lc.inside = !edge;
  return lc.ordered;
}

// Scratch that only grows: a resize back up would zero-fill it every step.
inline void grow(std::vector<double>& v, std::size_t size) {
  if (v.size() < size) v.resize(size);
}

// Zero cells padding the per-cell sums at each end (DDMP sub-points reach two cells over).
constexpr std::size_t kPad = 2;

// Pass 2: per-cell sums of NS per-particle fields (m, m f, m v, m v f, then the force
// fields), fields(q, out) computing particle q's, into S[f * stride + cell + kPad]
// (zeroed here; pads stay zero). Each cell's sum is taken in particle order.
template <int NS, class Fields>
[[gnu::always_inline]] inline void cell_sums(const int* __restrict cell, std::size_t n, bool ordered,
                                             std::size_t stride, double* __restrict S, Fields fields) {
  std::fill(S, S + NS * stride, 0.0);
  // Run by run (consecutive particles of one cell): the sums of different runs are
  // independent, so the core overlaps them, and each run touches memory once. In cell
  // order, which 1-D particles keep unless they cross, a run is the whole cell and is
  // stored; otherwise runs are added.
  double a[NS], b[NS];
  std::size_t q = 0;
  while (q < n) {
    const int c = cell[q];
    fields(q, a);
    for (++q; cell[q] == c; ++q) {  // cell[n] = -1 ends the last run
      fields(q, b);
#pragma GCC unroll 16
      for (int f = 0; f < NS; ++f) a[f] += b[f];
    }
    double* s = S + c + kPad;
    if (ordered) {
#pragma GCC unroll 16
      for (int f = 0; f < NS; ++f) s[f * stride] = a[f];
    } else {
#pragma GCC unroll 16
      for (int f = 0; f < NS; ++f) s[f * stride] += a[f];
    }
  }
}

// The mass and momentum fields of every point: m, m f, m v, m v f.
[[gnu::always_inline]] inline void mass_fields(double m, double v, double f, double* out) {
  const double mv = m * v;
  out[0] = m, out[1] = m * f, out[2] = mv, out[3] = mv * f;
}

// Pass 3, mass and momentum: node i takes (sum m - sum m f) of cell i and sum m f of
// cell i-1 (S = 1 - f, f). Written, not accumulated: no fill, no chain through memory.
void node_mass_momentum(const double* __restrict S, std::size_t stride, int cells, Grid<1>& g) {
  const double* __restrict S0 = S + kPad;
  const double* __restrict S1 = S0 + stride;
  const double* __restrict S2 = S1 + stride;
  const double* __restrict S3 = S2 + stride;
  double* __restrict M = g.mass.data() + Grid<1>::ghost;
  double* __restrict P = g.momentum[0].data() + Grid<1>::ghost;
#pragma omp simd
  for (int c = 0; c <= cells; ++c) {
    M[c] = S1[c - 1] + (S0[c] - S1[c]);
    P[c] = S3[c - 1] + (S2[c] - S3[c]);
  }
  g.mass.front() = g.mass.back() = 0.0;
  g.momentum[0].front() = g.momentum[0].back() = 0.0;
}

// The DDMP operator D (eq. 3.31), kept per node storage index.
void ddmp_table(const Grid<1>& g, LinearCells& lc) {
  if (lc.dm.size() == g.storage) return;
  DdmpTable t(g);
  lc.dm = t.dm, lc.dc = t.d0, lc.dp = t.dp;
}

// A sub-point's cell and weights (eq. 3.31 at xi): as add_ddmp_gradient.
struct SubWeights {
  int c;
  double a, b0, b1;  // alpha, (1 - alpha)(1 - f), (1 - alpha) f
};
inline SubWeights sub_weights(double xi, double top) {
  const Cell cf = cell_of(xi, top);
  const double a = alpha(cf.f), b = 1.0 - a;
  return {static_cast<int>(cf.c), a, b * (1.0 - cf.f), b * cf.f};
}

// Sub-point s of a particle at xi with half width h and spacing step (cell units), as
// evaluate_ddmp_subpoints places them.
inline double sub_h(double len, double inv, int n_sub) {
  return 0.5 * len * inv * (1.0 - 1.0 / n_sub);
}
inline double sub_step(double h, int n_sub) { return n_sub > 1 ? 2.0 * h / (n_sub - 1) : 0.0; }

// out = sqrt(in) elementwise, in >= 0. The square root is most of the cost of the DDMP
// weights (alpha, eq. 3.27), and the divider takes many cycles per vector. With AVX-512:
// the 14-bit reciprocal square root and two Newton steps (14 -> 28 -> 56 bits), then
// sqrt(in) = in * (1 / sqrt(in)): within an ulp or two of the correctly rounded root. Otherwise
// the SIMD square root (std::sqrt keeps errno's slow path in a loop and stops it
// vectorising; the SIMD one is the same correctly rounded IEEE operation).
void sqrt_all(std::size_t n, const double* __restrict in, double* __restrict out) {
  std::size_t q = 0;
#if defined(__AVX512F__)
  const __m512d half = _mm512_set1_pd(0.5), three_halves = _mm512_set1_pd(1.5);
  const __m512d zero = _mm512_setzero_pd();
  for (; q + 8 <= n; q += 8) {
    const __m512d r = _mm512_loadu_pd(in + q);
    const __mmask8 pos = _mm512_cmp_pd_mask(r, zero, _CMP_GT_OQ);
    const __m512d hr = _mm512_mul_pd(half, r);
    __m512d y = _mm512_maskz_rsqrt14_pd(pos, r);
    y = _mm512_mul_pd(y, _mm512_fnmadd_pd(_mm512_mul_pd(hr, y), y, three_halves));
    y = _mm512_mul_pd(y, _mm512_fnmadd_pd(_mm512_mul_pd(hr, y), y, three_halves));
    _mm512_storeu_pd(out + q, _mm512_maskz_mul_pd(pos, r, y));
  }
#elif defined(__AVX__)
  for (; q + 4 <= n; q += 4) _mm256_storeu_pd(out + q, _mm256_sqrt_pd(_mm256_loadu_pd(in + q)));
#elif defined(__SSE2__)
  for (; q + 2 <= n; q += 2) _mm_storeu_pd(out + q, _mm_sqrt_pd(_mm_loadu_pd(in + q)));
#endif
  for (; q < n; ++q) out[q] = std::sqrt(in[q]);
}

// DDMP weights of every particle: W[0..2] = alpha, (1-alpha)(1-f), (1-alpha) f at the
// particle (as ddmp_alpha and add_ddmp_gradient). `tmp`: 2 n scratch.
[[gnu::noinline]] void ddmp_weights(std::size_t n, const double* __restrict frac, double* __restrict W,
                  double* __restrict tmp) {
  double* __restrict r = tmp;
  double* __restrict sq = tmp + n;
#pragma omp simd
  for (std::size_t q = 0; q < n; ++q) r[q] = 4.0 * frac[q] * (1.0 - frac[q]);
  sqrt_all(n, r, sq);
#pragma omp simd
  for (std::size_t q = 0; q < n; ++q) {
    const double f = frac[q], a = 0.5 * r[q] * sq[q], b = 1.0 - a;
    W[q] = a, W[n + q] = b * (1.0 - f), W[2 * n + q] = b * f;
  }
}

// Sub-point weights of every particle (eqs. 3.31, 6.1-6.3), averaged over the n_sub
// points (equal volumes, eq. 6.2) placed as evaluate_ddmp_subpoints places them, summed
// in their order, and sorted by the sub-point's cell relative to the particle's cell c.
// In plain DDMP's layout, W[0..2] = <alpha> in cell c and <(1-alpha) S_j> at nodes c and
// c+1 (S_j the hat of the sub-point's cell). Particles with sub-points in cells c-1 or
// c+1 are listed in `mixed`, with Wx[4 k ..] = <alpha> in cells c-1, c+1 and
// <(1-alpha) S_j> at nodes c-1, c+2 for the k-th. Returns whether any particle has a
// sub-point further away (far[q]; those are handled apart).
//
// Most particles keep all their sub-points in their own cell: their fraction is xi - c,
// with no cell search or sorting. Those go eight at a time in registers (AVX-512) or
// chunk by chunk; the mixed ones chunk by chunk over their list.
[[gnu::noinline]] int subpoint_weights(std::size_t n, const double* __restrict x,
                                       const double* __restrict len, const int* __restrict cell,
                                       double x0, double inv, double top, int ns,
                                       double* __restrict W, int* __restrict far,
                                       std::vector<int>& mixed, std::vector<double>& Wx) {
  constexpr int B = 64;  // a chunk's sums and scratch stay in L1
  const double w = 1.0 / ns;
  mixed.clear();
  std::size_t done = 0;
#if defined(__AVX512F__)
  // Eight particles at a time, every sub-point in registers (the same arithmetic as the
  // loops below, without contraction, and the square root of sqrt_all).
  const __m512d vx0 = _mm512_set1_pd(x0), vinv = _mm512_set1_pd(inv), vw = _mm512_set1_pd(w);
  const __m512d hfac = _mm512_set1_pd(0.5), keep = _mm512_set1_pd(1.0 - 1.0 / ns);
  const __m512d one = _mm512_set1_pd(1.0), four = _mm512_set1_pd(4.0), zero = _mm512_setzero_pd();
  const __m512d three_halves = _mm512_set1_pd(1.5), vtop1 = _mm512_set1_pd(top - 1.0);
  const __m512d span = _mm512_set1_pd(ns - 1), two = _mm512_set1_pd(2.0);
  for (; done + 8 <= n; done += 8) {
    const std::size_t q = done;
    const __m512d xi = _mm512_mul_pd(_mm512_sub_pd(_mm512_loadu_pd(x + q), vx0), vinv);
    // sub_h, sub_step
    const __m512d h = _mm512_mul_pd(_mm512_mul_pd(_mm512_mul_pd(hfac, _mm512_loadu_pd(len + q)), vinv), keep);
    const __m512d step = ns > 1 ? _mm512_div_pd(_mm512_mul_pd(two, h), span) : zero;
    const __m512d c = _mm512_cvtepi32_pd(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell + q)));
    const __m512d lo = _mm512_sub_pd(xi, h);
    const __m512d hi = _mm512_add_pd(lo, _mm512_mul_pd(span, step));
    const __mmask8 own = _mm512_cmp_pd_mask(lo, c, _CMP_GE_OQ) &
                         _mm512_cmp_pd_mask(hi, _mm512_add_pd(c, one), _CMP_LT_OQ) &
                         _mm512_cmp_pd_mask(c, vtop1, _CMP_LE_OQ);
    __m512d a1 = zero, a4 = zero, a5 = zero;
    for (int sp = 0; sp < ns; ++sp) {
      const __m512d f = _mm512_sub_pd(_mm512_add_pd(lo, _mm512_mul_pd(_mm512_set1_pd(sp), step)), c);
      const __m512d omf = _mm512_sub_pd(one, f);
      const __m512d r = _mm512_mul_pd(_mm512_mul_pd(four, f), omf);
      const __mmask8 pos = _mm512_cmp_pd_mask(r, zero, _CMP_GT_OQ);
      const __m512d hr = _mm512_mul_pd(hfac, r);
      __m512d y = _mm512_maskz_rsqrt14_pd(pos, r);
      y = _mm512_mul_pd(y, _mm512_fnmadd_pd(_mm512_mul_pd(hr, y), y, three_halves));
      y = _mm512_mul_pd(y, _mm512_fnmadd_pd(_mm512_mul_pd(hr, y), y, three_halves));
      const __m512d sq = _mm512_maskz_mul_pd(pos, r, y);
      const __m512d al = _mm512_mul_pd(_mm512_mul_pd(hfac, r), sq), be = _mm512_sub_pd(one, al);
      a1 = _mm512_add_pd(a1, al);
      a4 = _mm512_add_pd(a4, _mm512_mul_pd(be, omf));
      a5 = _mm512_add_pd(a5, _mm512_mul_pd(be, f));
    }
    _mm512_storeu_pd(W + q, _mm512_mul_pd(a1, vw));
    _mm512_storeu_pd(W + n + q, _mm512_mul_pd(a4, vw));
    _mm512_storeu_pd(W + 2 * n + q, _mm512_mul_pd(a5, vw));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(far + q), _mm256_setzero_si256());
    for (unsigned m = static_cast<unsigned char>(~own); m; m &= m - 1)
      mixed.push_back(static_cast<int>(q + __builtin_ctz(m)));
  }
#endif
  for (std::size_t q0 = done; q0 < n; q0 += B) {
    const int nb = static_cast<int>(std::min<std::size_t>(B, n - q0));
    alignas(64) double df[B], fr[B], r[B], sq[B], a1[B], a4[B], a5[B];
    alignas(64) int own[B];
#pragma omp simd
    for (int j = 0; j < nb; ++j) {
      const std::size_t q = q0 + j;
      const double xi = (x[q] - x0) * inv;
      const double h = sub_h(len[q], inv, ns), step = sub_step(h, ns);
      const double c = cell[q], lo = xi - h, hi = lo + (ns - 1) * step;
      own[j] = (lo >= c) & (hi < c + 1.0) & (c <= top - 1.0);
      df[j] = step;
      a1[j] = a4[j] = a5[j] = 0.0;
    }
    for (int sp = 0; sp < ns; ++sp) {
      // As cell_of: inside its own cell a sub-point's fraction is (start + s step) - c.
#pragma omp simd
      for (int j = 0; j < nb; ++j) {
        const std::size_t q = q0 + j;
        const double xi = (x[q] - x0) * inv;
        const double h = sub_h(len[q], inv, ns);
        const double f = (xi - h + sp * df[j]) - static_cast<double>(cell[q]);
        fr[j] = f;
        r[j] = 4.0 * f * (1.0 - f);
      }
      sqrt_all(nb, r, sq);
#pragma omp simd
      for (int j = 0; j < nb; ++j) {
        const double f = fr[j], al = 0.5 * r[j] * sq[j], be = 1.0 - al;
        a1[j] += al;
        a4[j] += be * (1.0 - f);
        a5[j] += be * f;
      }
    }
    for (int j = 0; j < nb; ++j) {
      const std::size_t q = q0 + j;
      W[q] = a1[j] * w, W[n + q] = a4[j] * w, W[2 * n + q] = a5[j] * w;
      far[q] = 0;
      if (!own[j]) mixed.push_back(static_cast<int>(q));
    }
  }
  // Particles whose sub-points reach into other cells: sorted by cell relative to the
  // particle's, as the sums above, chunk by chunk over the list.
  Wx.resize(4 * mixed.size());
  int any = 0;
  for (std::size_t k0 = 0; k0 < mixed.size(); k0 += B) {
    const int nb = static_cast<int>(std::min<std::size_t>(B, mixed.size() - k0));
    const int* __restrict ids = mixed.data() + k0;
    alignas(64) double start[B], step[B], cq[B], fr[B], r[B], sq[B], d[B], acc[7][B];
    alignas(64) int out[B];
    for (int j = 0; j < nb; ++j) {
      const std::size_t q = static_cast<std::size_t>(ids[j]);
      const double xi = (x[q] - x0) * inv;
      const double h = sub_h(len[q], inv, ns);
      start[j] = xi - h, step[j] = sub_step(h, ns), cq[j] = cell[q];
      out[j] = 0;
      for (int k = 0; k < 7; ++k) acc[k][j] = 0.0;
    }
    for (int sp = 0; sp < ns; ++sp) {
#pragma omp simd
      for (int j = 0; j < nb; ++j) {
        const Cell cf = cell_of(start[j] + sp * step[j], top);
        fr[j] = cf.f;
        r[j] = 4.0 * cf.f * (1.0 - cf.f);
        d[j] = cf.c - cq[j];
      }
      sqrt_all(nb, r, sq);
#pragma omp simd
      for (int j = 0; j < nb; ++j) {
        const double f = fr[j], al = 0.5 * r[j] * sq[j], be = 1.0 - al;
        const double b0 = be * (1.0 - f), b1 = be * f;
        const bool m = d[j] == -1.0, z = d[j] == 0.0, p = d[j] == 1.0;
        out[j] |= !(m | z | p);
        acc[0][j] += m ? al : 0.0;
        acc[1][j] += z ? al : 0.0;
        acc[2][j] += p ? al : 0.0;
        acc[3][j] += m ? b0 : 0.0;
        acc[4][j] += (m ? b1 : 0.0) + (z ? b0 : 0.0);
        acc[5][j] += (z ? b1 : 0.0) + (p ? b0 : 0.0);
        acc[6][j] += p ? b1 : 0.0;
      }
    }
    for (int j = 0; j < nb; ++j) {
      const std::size_t q = static_cast<std::size_t>(ids[j]);
      W[q] = acc[1][j] * w, W[n + q] = acc[4][j] * w, W[2 * n + q] = acc[5][j] * w;
      double* wx = Wx.data() + 4 * (k0 + j);
      wx[0] = acc[0][j] * w, wx[1] = acc[2][j] * w, wx[2] = acc[3][j] * w, wx[3] = acc[6][j] * w;
      far[q] = out[j];
      any |= out[j];
    }
  }
  return any;
}

}  // namespace

void p2g_linear(const Grid<1>&, const Particles<1>& p, bool reference_volume,
                bool no_viscous_pressure, LinearCells& lc, Grid<1>& g) {
  const int cells = g.cells[0];
  const bool ordered = locate_all(g, p, lc);
  const std::size_t stride = static_cast<std::size_t>(cells) + 2 * kPad;
  lc.sums.resize(5 * stride);
  const double* __restrict vol = reference_volume ? p.volume0.data() : p.volume.data();
  const double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  const double* __restrict grad = lc.grad.data();
  const std::size_t n = p.size();
  const double* __restrict m = p.mass.data();
  const double* __restrict v = p.v[0].data();
  const double* __restrict frac = lc.frac.data();
  double* S = lc.sums.data();
  // Every particle inside the grid and no viscosity (the common case): the gradient is
  // 1/dx throughout, applied per node, and q is not read.
  const bool plain = no_viscous_pressure && lc.inside;
  if (plain)
    cell_sums<5>(lc.cell.data(), n, ordered, stride, S, [&](std::size_t q, double* out) {
      mass_fields(m[q], v[q], frac[q], out);
      out[4] = vol[q] * sig[q];
    });
  else
    cell_sums<5>(lc.cell.data(), n, ordered, stride, S, [&](std::size_t q, double* out) {
      mass_fields(m[q], v[q], frac[q], out);
      out[4] = vol[q] * (sig[q] - qv[q]) * grad[q];
    });
  node_mass_momentum(S, stride, cells, g);
  // The force is +V sigma/dx from cell i and -V sigma/dx from cell i-1 (G = -1/dx, +1/dx).
  const double* __restrict S4 = S + 4 * stride + kPad;
  double* __restrict F = g.force[0].data() + Grid<1>::ghost;
  const double scale = plain ? g.inv_dx[0] : 1.0;
#pragma omp simd
  for (int c = 0; c <= cells; ++c) F[c] = scale * (S4[c] - S4[c - 1]);
  g.force[0].front() = g.force[0].back() = 0.0;
}

namespace {

// Per-cell node values for g2p: dv at the left node and its jump, and the same for the
// velocity v^{n+1/2} or v^L that moves the particle and gives grad v.
void cell_tables(const Grid<1>& g, LinearCells& lc, bool midpoint) {
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const int cells = g.cells[0];
  const double* __restrict VL = g.velocity_L[0].data() + Grid<1>::ghost;
  const double* __restrict VN = g.velocity[0].data() + Grid<1>::ghost;
  // Padded: g2p_elastic_ordered loads eight entries from any cell on.
  lc.d0.resize(cells + 8);
  lc.dd.resize(cells + 8);
  lc.g0.resize(cells + 8);
  lc.dg.resize(cells + 8);
  double* __restrict d0 = lc.d0.data();
  double* __restrict dd = lc.dd.data();
  double* __restrict g0 = lc.g0.data();
  double* __restrict dg = lc.dg.data();
#pragma omp simd
  for (int c = 0; c < cells; ++c) {
    const double a = VL[c] - VN[c], b = VL[c + 1] - VN[c + 1];
    const double u = wl * VL[c] + wn * VN[c], w = wl * VL[c + 1] + wn * VN[c + 1];
    d0[c] = a, dd[c] = b - a, g0[c] = u, dg[c] = w - u;
  }
}

}  // namespace

double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                  Particles<1>& p) {
  cell_tables(g, lc, midpoint);
  const std::size_t n = p.size();
  const double* __restrict d0 = lc.d0.data();
  const double* __restrict dd = lc.dd.data();
  const double* __restrict g0 = lc.g0.data();
  const double* __restrict dg = lc.dg.data();
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

namespace {

// The per-cell g2p tables at every particle (pc[k * n + q] = table_k[cell[q]]), for the
// portable kernel (g2p_elastic_ordered reads the tables directly).
void expand_cells(LinearCells& lc, std::size_t n) {
  lc.pc.resize(4 * n);
  const double* tab[4] = {lc.d0.data(), lc.dd.data(), lc.g0.data(), lc.dg.data()};
  const int* __restrict cell = lc.cell.data();
  double* __restrict out = lc.pc.data();
  std::size_t q = 0;
  for (; q < n; ++q)
    for (int k = 0; k < 4; ++k) out[k * n + q] = tab[k][cell[q]];
}

// The fused kernel with the volume choice fixed at compile time (so the loop vectorises).
template <bool SmallStrain>
[[gnu::noinline]] double g2p_elastic_kernel(const LinearCells& lc, double dt, double dtm, double E,
                                            Particles<1>& p, double& work) {
  const std::size_t n = p.size();
  const double* __restrict d0 = lc.pc.data();  // the cell's tables, at each particle
  const double* __restrict dd = d0 + n;
  const double* __restrict g0 = dd + n;
  const double* __restrict dg = g0 + n;
  const double* __restrict frac = lc.frac.data();
  const double* __restrict grad = lc.grad.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  double* __restrict V = p.volume.data();
  const double* __restrict V0 = p.volume0.data();
  double* __restrict eps = p.strain[0].data();
  double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  double check = 0.0, w = 0.0;
#pragma omp simd reduction(+ : check, w)
  for (std::size_t q = 0; q < n; ++q) {
    const double f = frac[q];
    const double vq = v[q] + (d0[q] + f * dd[q]);
    const double xq = x[q] + dtm * (g0[q] + f * dg[q]);
    const double Lq = dg[q] * grad[q];
    v[q] = vq, x[q] = xq, L[q] = Lq;
    check += vq + xq;
    // work_and_volumes, then LinearElastic::update_stress (eps += dt 0.5 (L + L) is
    // eps += dt L exactly).
    const double Vq = V[q];
    w += (SmallStrain ? V0[q] : Vq) * (sig[q] - qv[q]) * Lq;
    V[q] = Vq * (1.0 + dt * Lq);
    const double e = eps[q] + dt * Lq;
    eps[q] = e;
    sig[q] = E * e;
  }
  work = w;
  return check;
}

#if defined(__AVX512F__)
// g2p_elastic_kernel without the expanded tables, for particles in cell order and
// without viscosity (q = 0): eight particles whose cells lie within eight of the first
// take their cells' table values by one load and a permute each, in registers. Other
// blocks, and the last, go particle by particle through the same arithmetic.
template <bool SmallStrain, bool Inside>
[[gnu::noinline]] double g2p_elastic_ordered(const LinearCells& lc, double dt, double dtm, double E,
                                             double inv, Particles<1>& p, double& work) {
  const std::size_t n = p.size();
  const double* __restrict T0 = lc.d0.data();
  const double* __restrict T1 = lc.dd.data();
  const double* __restrict T2 = lc.g0.data();
  const double* __restrict T3 = lc.dg.data();
  const int* __restrict cell = lc.cell.data();
  const double* __restrict frac = lc.frac.data();
  const double* __restrict grad = lc.grad.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  double* __restrict V = p.volume.data();
  const double* __restrict V0 = p.volume0.data();
  double* __restrict eps = p.strain[0].data();
  double* __restrict sig = p.stress[0].data();
  const __m512d vdt = _mm512_set1_pd(dt), vdtm = _mm512_set1_pd(dtm), vE = _mm512_set1_pd(E);
  const __m512d one = _mm512_set1_pd(1.0), vinv = _mm512_set1_pd(inv);
  __m512d check = _mm512_setzero_pd(), w = _mm512_setzero_pd();
  double check1 = 0.0, w1 = 0.0;
  auto one_particle = [&](std::size_t q) {
    const int c = cell[q];
    const double f = frac[q];
    const double vq = v[q] + std::fma(f, T1[c], T0[c]);
    const double xq = std::fma(dtm, std::fma(f, T3[c], T2[c]), x[q]);
    const double Lq = T3[c] * grad[q];
    v[q] = vq, x[q] = xq, L[q] = Lq;
    check1 += vq + xq;
    const double Vq = V[q];
    w1 += (SmallStrain ? V0[q] : Vq) * sig[q] * Lq;
    V[q] = Vq * std::fma(dt, Lq, 1.0);
    const double e = std::fma(dt, Lq, eps[q]);
    eps[q] = e;
    sig[q] = E * e;
  };
  std::size_t q = 0;
  for (; q + 8 <= n; q += 8) {
    const int c0 = cell[q];
    if (cell[q + 7] - c0 >= 8) {
      for (std::size_t r = q; r < q + 8; ++r) one_particle(r);
      continue;
    }
    // maskz forms: GCC 12 warns on the unmasked ones' undefined pass-through operand.
    const __m256i ci = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell + q));
    const __m512i idx = _mm512_maskz_cvtepi32_epi64(0xFF, _mm256_sub_epi32(ci, _mm256_set1_epi32(c0)));
    const __m512d d0 = _mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(T0 + c0));
    const __m512d dd = _mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(T1 + c0));
    const __m512d g0 = _mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(T2 + c0));
    const __m512d dg = _mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(T3 + c0));
    const __m512d f = _mm512_loadu_pd(frac + q);
    const __m512d vq = _mm512_add_pd(_mm512_loadu_pd(v + q), _mm512_fmadd_pd(f, dd, d0));
    const __m512d xq = _mm512_fmadd_pd(vdtm, _mm512_fmadd_pd(f, dg, g0), _mm512_loadu_pd(x + q));
    const __m512d Lq = _mm512_mul_pd(dg, Inside ? vinv : _mm512_loadu_pd(grad + q));
    _mm512_storeu_pd(v + q, vq);
    _mm512_storeu_pd(x + q, xq);
    _mm512_storeu_pd(L + q, Lq);
    check = _mm512_add_pd(check, _mm512_add_pd(vq, xq));
    const __m512d Vq = _mm512_loadu_pd(V + q);
    const __m512d Vw = SmallStrain ? _mm512_loadu_pd(V0 + q) : Vq;
    w = _mm512_fmadd_pd(_mm512_mul_pd(Vw, _mm512_loadu_pd(sig + q)), Lq, w);
    _mm512_storeu_pd(V + q, _mm512_mul_pd(Vq, _mm512_fmadd_pd(vdt, Lq, one)));
    const __m512d e = _mm512_fmadd_pd(vdt, Lq, _mm512_loadu_pd(eps + q));
    _mm512_storeu_pd(eps + q, e);
    _mm512_storeu_pd(sig + q, _mm512_mul_pd(vE, e));
  }
  for (; q < n; ++q) one_particle(q);
  alignas(64) double wl[8], cl[8];
  _mm512_store_pd(wl, w);
  _mm512_store_pd(cl, check);
  for (int k = 0; k < 8; ++k) w1 += wl[k], check1 += cl[k];
  work = w1;
  return check1;
}
#endif

}  // namespace

double g2p_linear_elastic(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                          bool small_strain, [[maybe_unused]] bool no_viscous_pressure, double E,
                          Particles<1>& p, double& stress_work) {
  cell_tables(g, lc, midpoint);
  const double dtm = move ? dt : 0.0;
  double w = 0.0;
#if defined(__AVX512F__)
  if (lc.ordered && no_viscous_pressure) {
    const double inv = g.inv_dx[0];
    const double check =
        small_strain ? (lc.inside ? g2p_elastic_ordered<true, true>(lc, dt, dtm, E, inv, p, w)
                                  : g2p_elastic_ordered<true, false>(lc, dt, dtm, E, inv, p, w))
                     : (lc.inside ? g2p_elastic_ordered<false, true>(lc, dt, dtm, E, inv, p, w)
                                  : g2p_elastic_ordered<false, false>(lc, dt, dtm, E, inv, p, w));
    stress_work += dt * w;
    return check;
  }
#endif
  expand_cells(lc, p.size());
  const double check = small_strain ? g2p_elastic_kernel<true>(lc, dt, dtm, E, p, w)
                                    : g2p_elastic_kernel<false>(lc, dt, dtm, E, p, w);
  stress_work += dt * w;
  return check;
}

void p2g_ddmp(const Grid<1>&, const Particles<1>& p, bool reference_volume, int subpoints,
              LinearCells& lc, Grid<1>& g) {
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  const double top = cells, inv = g.inv_dx[0], x0 = g.lower[0];
  const bool sub = subpoints > 0;
  ddmp_table(g, lc);
  const bool ordered = locate_all(g, p, lc);
  const int nw = 3;  // weights per particle (sub-points in other cells: lc.Wx)
  lc.W.resize(nw * n);
  lc.mixed.clear();
  lc.stray.clear();
  const int* __restrict cell = lc.cell.data();
  const double* __restrict x = p.x[0].data();
  if (!sub) {
    grow(lc.val, 2 * n);
    ddmp_weights(n, lc.frac.data(), lc.W.data(), lc.val.data());
  } else {
    lc.far.resize(n);
    if (subpoint_weights(n, x, p.length[0].data(), cell, x0, inv, top, subpoints, lc.W.data(),
                         lc.far.data(), lc.mixed, lc.Wx))
      for (std::size_t q = 0; q < n; ++q)
        if (lc.far[q]) lc.stray.push_back(static_cast<int>(q));
  }
  // Pass 2 over m, m f, m v, m v f and V sigma times each weight.
  const std::size_t stride = static_cast<std::size_t>(cells) + 2 * kPad;
  const int ns = 4 + nw;
  lc.sums.resize(ns * stride);
  const double* __restrict vol = reference_volume ? p.volume0.data() : p.volume.data();
  const double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  const double* __restrict W = lc.W.data();
  const double* __restrict m = p.mass.data();
  const double* __restrict v = p.v[0].data();
  const double* __restrict frac = lc.frac.data();
  double* S = lc.sums.data();
  auto fields = [&]<int NW>(std::size_t q, double* out) {
    mass_fields(m[q], v[q], frac[q], out);
    const double vs = vol[q] * (sig[q] - qv[q]);
#pragma GCC unroll 8
    for (int k = 0; k < NW; ++k) out[4 + k] = vs * W[k * n + q];
  };
  cell_sums<7>(cell, n, ordered, stride, S,
               [&](std::size_t q, double* out) { fields.template operator()<3>(q, out); });
  node_mass_momentum(S, stride, cells, g);
  // f_i = -sum_p V sigma Gbar_ip: the alpha part gives +-V sigma alpha/dx at the two
  // nodes of the point's cell; the rest is -sum_j D_ji Q_j with Q_j the hat-weighted
  // nodal sum of V sigma (1 - alpha) (eq. 3.31). Per cell: SA[c]; per node: Q[j].
  const double* __restrict F0 = S + 4 * stride + kPad;  // force fields by particle cell
  lc.vg.resize(cells + 2);
  lc.Dv.resize(g.storage + 8);  // padded: eight-wide loads from any node
  double* __restrict SA = lc.vg.data() + 1;                // cells -1 .. cells
  double* __restrict Q = lc.Dv.data() + Grid<1>::ghost;   // nodes -1 .. cells + 1
  SA[-1] = SA[cells] = 0.0;
  Q[-1] = Q[cells + 1] = 0.0;
  const double* __restrict A = F0;
  const double* __restrict B = A + stride;
  const double* __restrict C = B + stride;
#pragma omp simd
  for (int c = 0; c < cells; ++c) SA[c] = A[c];
#pragma omp simd
  for (int j = 0; j <= cells; ++j) Q[j] = B[j] + C[j - 1];
  // Sub-points in the neighbouring cells (their cells and nodes lie inside the grid).
  for (std::size_t k = 0; k < lc.mixed.size(); ++k) {
    const int q = lc.mixed[k], c = cell[q];
    const double vs = vol[q] * (sig[q] - qv[q]);
    const double* wx = lc.Wx.data() + 4 * k;
    SA[c - 1] += vs * wx[0], SA[c + 1] += vs * wx[1];
    Q[c - 1] += vs * wx[2], Q[c + 2] += vs * wx[3];
  }
  const double* __restrict dm = lc.dm.data() + Grid<1>::ghost;
  const double* __restrict dc = lc.dc.data() + Grid<1>::ghost;
  const double* __restrict dp = lc.dp.data() + Grid<1>::ghost;
  double* __restrict F = g.force[0].data() + Grid<1>::ghost;
#pragma omp simd
  for (int i = 0; i <= cells; ++i)
    F[i] = inv * (SA[i] - SA[i - 1]) - (dp[i - 1] * Q[i - 1] + dc[i] * Q[i] + dm[i + 1] * Q[i + 1]);
  g.force[0].front() = g.force[0].back() = 0.0;
  // Sub-points more than a cell from the particle's cell: their own nodes, directly.
  for (const int q : lc.stray) {
    const double sv = vol[q] * (sig[q] - qv[q]) / subpoints;
    const double xi = (x[q] - x0) * inv, h = sub_h(p.length[0][q], inv, subpoints),
                 step = sub_step(h, subpoints);
    for (int s = 0; s < subpoints; ++s) {
      const SubWeights sw = sub_weights(xi - h + s * step, top);
      const int c = sw.c;
      if (std::abs(c - cell[q]) <= 1) continue;
      F[c] += inv * sv * sw.a;
      F[c + 1] -= inv * sv * sw.a;
      for (int j = c; j <= c + 1; ++j) {
        const double Qj = sv * (j == c ? sw.b0 : sw.b1);
        F[j - 1] -= dm[j] * Qj;
        F[j] -= dc[j] * Qj;
        F[j + 1] -= dp[j] * Qj;
      }
    }
  }
}

namespace {

// grad v from the DDMP weights: alpha dv/dx in the point's cell plus the hat-weighted
// nodal gradients Dv (eq. 3.31); sub-points in other cells are added by the caller.
[[gnu::noinline]] double ddmp_g2p_kernel(const LinearCells& lc, std::size_t n, double dtm,
                                         double inv, Particles<1>& p) {
  const double* __restrict d0 = lc.d0.data();
  const double* __restrict dd = lc.dd.data();
  const double* __restrict g0 = lc.g0.data();
  const double* __restrict dg = lc.dg.data();
  const double* __restrict Dn = lc.Dv.data() + Grid<1>::ghost;  // by node, -1 .. cells + 1
  const int* __restrict cell = lc.cell.data();
  const double* __restrict frac = lc.frac.data();
  const double* __restrict W = lc.W.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  double check = 0.0;
  std::size_t q0 = 0;
#if defined(__AVX512F__)
  // In cell order: eight particles whose cells lie within eight of the first take the
  // tables by one load and a permute each (as g2p_elastic_ordered).
  if (lc.ordered) {
    const __m512d vinv = _mm512_set1_pd(inv), vdtm = _mm512_set1_pd(dtm);
    __m512d vcheck = _mm512_setzero_pd();
    for (; q0 + 8 <= n; q0 += 8) {
      const int c0 = cell[q0];
      if (cell[q0 + 7] - c0 >= 8) break;  // the rest one by one
      const __m256i ci = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell + q0));
      const __m512i idx = _mm512_maskz_cvtepi32_epi64(0xFF, _mm256_sub_epi32(ci, _mm256_set1_epi32(c0)));
      auto at = [&](const double* t) { return _mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(t + c0)); };
      const __m512d f = _mm512_loadu_pd(frac + q0);
      const __m512d vq = _mm512_add_pd(_mm512_loadu_pd(v + q0), _mm512_fmadd_pd(f, at(dd), at(d0)));
      const __m512d dgc = at(dg);
      const __m512d xq = _mm512_fmadd_pd(vdtm, _mm512_fmadd_pd(f, dgc, at(g0)), _mm512_loadu_pd(x + q0));
      _mm512_storeu_pd(v + q0, vq);
      _mm512_storeu_pd(x + q0, xq);
      const __m512d Lq = _mm512_fmadd_pd(
          _mm512_loadu_pd(W + q0), _mm512_mul_pd(vinv, dgc),
          _mm512_fmadd_pd(_mm512_loadu_pd(W + n + q0), at(Dn),
                          _mm512_mul_pd(_mm512_loadu_pd(W + 2 * n + q0), at(Dn + 1))));
      _mm512_storeu_pd(L + q0, Lq);
      vcheck = _mm512_add_pd(vcheck, _mm512_add_pd(vq, xq));
    }
    alignas(64) double cl[8];
    _mm512_store_pd(cl, vcheck);
    for (int k = 0; k < 8; ++k) check += cl[k];
  }
#endif
#pragma omp simd reduction(+ : check)
  for (std::size_t q = q0; q < n; ++q) {
    const int c = cell[q];
    const double f = frac[q];
    const double vq = v[q] + (d0[c] + f * dd[c]);
    const double xq = x[q] + dtm * (g0[c] + f * dg[c]);
    v[q] = vq, x[q] = xq;
    L[q] = W[q] * inv * dg[c] + W[n + q] * Dn[c] + W[2 * n + q] * Dn[c + 1];
    check += vq + xq;
  }
  return check;
}

}  // namespace

double g2p_ddmp(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                int subpoints, Particles<1>& p) {
  cell_tables(g, lc, midpoint);
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const double top = cells, inv = g.inv_dx[0], x0 = g.lower[0];
  // Nodal gradient of the velocity that gives grad v: Dv_j = sum_i D_ji vg_i (ghosts 0).
  grow(lc.val, g.storage);  // free after p2g: scratch
  lc.Dv.resize(g.storage + 8);  // padded: eight-wide loads from any node
  const double* __restrict VL = g.velocity_L[0].data();
  const double* __restrict VN = g.velocity[0].data();
  double* __restrict vg = lc.val.data();
#pragma omp simd
  for (std::size_t i = 0; i < g.storage; ++i) vg[i] = wl * VL[i] + wn * VN[i];
  const double* __restrict dm = lc.dm.data();
  const double* __restrict dc = lc.dc.data();
  const double* __restrict dp = lc.dp.data();
  double* __restrict Dv = lc.Dv.data();
  const std::size_t last = g.storage - 1;
  Dv[0] = Dv[last] = 0.0;
#pragma omp simd
  for (std::size_t j = 1; j < last; ++j)
    Dv[j] = dm[j] * vg[j - 1] + dc[j] * vg[j] + dp[j] * vg[j + 1];
  // dg with a zero pad each side, for sub-points in the neighbouring cells.
  lc.vg.resize(cells + 2);
  lc.vg.front() = lc.vg.back() = 0.0;
  std::copy(lc.dg.begin(), lc.dg.begin() + cells, lc.vg.begin() + 1);
  const double* __restrict Dn = Dv + Grid<1>::ghost;
  // Sub-points more than a cell away, before x moves: their part of grad v.
  std::vector<double> extra(lc.stray.size(), 0.0);
  for (std::size_t k = 0; k < lc.stray.size(); ++k) {
    const std::size_t q = static_cast<std::size_t>(lc.stray[k]);
    const double xi = (p.x[0][q] - x0) * inv, h = sub_h(p.length[0][q], inv, subpoints),
                 step = sub_step(h, subpoints);
    double e = 0.0;
    for (int s = 0; s < subpoints; ++s) {
      const SubWeights sw = sub_weights(xi - h + s * step, top);
      if (std::abs(sw.c - lc.cell[q]) <= 1) continue;
      e += sw.a * inv * lc.dg[sw.c] + sw.b0 * Dn[sw.c] + sw.b1 * Dn[sw.c + 1];
    }
    extra[k] = e / subpoints;
  }
  const double dtm = move ? dt : 0.0;
  const double check = ddmp_g2p_kernel(lc, n, dtm, inv, p);
  double* L = p.grad_v[0].data();
  const double* __restrict dgp = lc.vg.data() + 1;  // dg with a zero each side
  for (std::size_t k = 0; k < lc.mixed.size(); ++k) {
    const int q = lc.mixed[k], c = lc.cell[q];
    const double* wx = lc.Wx.data() + 4 * k;
    L[q] += inv * (wx[0] * dgp[c - 1] + wx[1] * dgp[c + 1]) + (wx[2] * Dn[c - 1] + wx[3] * Dn[c + 2]);
  }
  for (std::size_t k = 0; k < lc.stray.size(); ++k) L[lc.stray[k]] += extra[k];
  return check;
}

}  // namespace mpmx::mpm::shape
