// The fused 1-D kernels, written once with Google Highway and compiled for every vector
// path of core/simd_targets.hpp; the entry points at the end dispatch to the best this
// machine has (or MPMX_ISA's). Everything above them is compiled once per path:
// hwy/foreach_target.h includes this file again for each.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the paths to compile
// clang-format on

#include "mpmx/mpm/fused1d/linear_fused.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "mpmx/core/isa.hpp"
#include "mpmx/mpm/fused1d/linear_fused_detail.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/hat.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "mpmx/mpm/fused1d/linear_fused.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

#include "mpmx/mpm/fused1d/simd.hpp"

HWY_BEFORE_NAMESPACE();
namespace mpmx::mpm::shape::HWY_NAMESPACE {

using namespace fused;
namespace hn = hwy::HWY_NAMESPACE;
using simd::D4;
using simd::DFull;

namespace {

#include "mpmx/material/linear_elastic_1d.inc"

// Pass 1 kernel: cell, fraction and gradient of every particle (as cell_of); returns
// whether any lies more than a cell past the grid (or is NaN), and in `edge` whether any
// lies past its ends at all (a zero gradient there). A vector at a time: the flags come
// from the running least and largest position and a running sum (NaN stays NaN); the
// cell is truncated in double and converted to int once, and the gradient is 1/dx where
// clamping to the grid left the point where it was.
[[gnu::noinline]] int locate_kernel(std::size_t n, const double* __restrict x, double x0, double inv, double top,
                  int* __restrict cell, double* __restrict frac, double* __restrict grad, int& edge) {
  const D4 d;
  using vdouble = hn::Vec<D4>;
  constexpr int K = simd::kLanes<D4>;
  const vdouble zero = hn::Zero(d), vtop = hn::Set(d, top), vinv = hn::Set(d, inv);
  const vdouble vx0 = hn::Set(d, x0), one = hn::Set(d, 1.0);
  vdouble lo = zero, hi = lo, total = zero;
  std::size_t q = 0;
  for (; q + K <= n; q += K) {
    const vdouble xi = (simd::load(d, x + q) - vx0) * vinv;
    lo = hn::Min(lo, xi), hi = hn::Max(hi, xi), total += xi;
    const vdouble xc = hn::Min(hn::Max(xi, zero), vtop);
    // xc >= 0: truncation is floor; the last cell takes the grid's end.
    const vdouble cd = hn::Trunc(hn::Min(xc, vtop - one));
    hn::StoreU(hn::DemoteTo(simd::DI<D4>(), cd), simd::DI<D4>(), cell + q);
    simd::store(frac + q, xc - cd);
    simd::store(grad + q, hn::IfThenElse(hn::Eq(xc, xi), vinv, zero));
  }
  double least = 0.0, largest = 0.0, sum = simd::sum(total);
  double lol[K], hil[K];
  simd::lanes(lo, lol), simd::lanes(hi, hil);
  for (int k = 0; k < K; ++k) least = std::min(least, lol[k]), largest = std::max(largest, hil[k]);
  for (; q < n; ++q) {
    const double xi = (x[q] - x0) * inv;
    least = std::min(least, xi), largest = std::max(largest, xi), sum += xi;
    const bool in = (xi >= 0.0) & (xi <= top);
    const Cell cf = cell_of(xi, top);
    cell[q] = static_cast<int>(cf.c);
    frac[q] = cf.f;
    grad[q] = in ? inv : 0.0;
  }
  edge = least < 0.0 || largest > top;
  return least < -1.0 || largest > top + 1.0 || sum != sum;
}

// Pass 1: locate every particle (stops the run for one off the grid). With check_order,
// sets whether the particles still lie in cell order (in 1-D they keep it unless they
// cross); without, leaves `ordered` as it was for ordered_sums to confirm.
void locate_all(const Grid<1>& g, const Particles<1>& p, LinearCells& lc, bool check_order = true) {
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
  lc.inside = !edge;
  if (!check_order) return;
  const int* __restrict cell = lc.cell.data();
  int unordered = 0;
#pragma omp simd reduction(| : unordered)
  for (std::size_t q = 1; q < n; ++q) unordered |= cell[q] < cell[q - 1];
  lc.ordered = !unordered;
}

// Scratch that only grows: a resize back up would zero-fill it every step.
inline void grow(std::vector<double>& v, std::size_t size) {
  if (v.size() < size) v.resize(size);
}

// Zero cells padding the per-cell sums at each end (DDMP sub-points reach two cells over).
constexpr std::size_t kPad = 2;

// Pass 2 for particles out of cell order: per-cell sums of NS per-particle fields (m, m f,
// m v, m v f, then the force fields), fields(q, out) computing particle q's, into
// S[f * stride + cell + kPad] (zeroed here; pads stay zero). Run by run (consecutive
// particles of one cell), each run added to its cell once.
template <int NS, class Fields>
[[gnu::always_inline]] inline void cell_sums(const int* __restrict cell, std::size_t n, std::size_t stride,
                                             double* __restrict S, Fields fields) {
  std::fill(S, S + NS * stride, 0.0);
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
#pragma GCC unroll 16
    for (int f = 0; f < NS; ++f) s[f * stride] += a[f];
  }
}

// The mass and momentum fields of a point, or of a vector of them: m, m f, m v, m v f.
template <class T>
[[gnu::always_inline]] inline void mass_fields(T m, T v, T f, T* out) {
  const T mv = m * v;
  out[0] = m, out[1] = m * f, out[2] = mv, out[3] = mv * f;
}

// Pass 2 for particles in cell order: where a vector's worth of particles share a cell
// (all of them at four or more per cell with four lanes), their fields go a vector at a time,
// summed down the run and across the lanes at its end; the rest of a run one by one. Every
// cell is written once, in order: a run's sums, or zero in the gaps between runs and in
// the pads (no fill). The order of the additions differs from cell_sums (the same to
// round-off). Where consecutive cells hold one vector each, two to four cells go at once.
// vfields(q, out): the NS fields of particles q .. q + kLanes - 1; sfields(q, out): one
// particle's. Returns whether the cells were in order after all (each run's above the
// last's); where not, S is not the sums, though every write stays inside it.
template <int NS, class D, class VFields, class SFields>
[[gnu::always_inline]] inline bool ordered_sums(D d, const int* __restrict cell, std::size_t n, std::size_t stride,
                                                double* __restrict S, VFields vfields, SFields sfields) {
  using vdouble = hn::Vec<D>;
  constexpr int K = simd::kLanes<D>, NG = (NS + 3) / 4;  // lane sums go four fields at a time
  std::size_t next = 0;  // the first cell of S not yet written
  bool in_order = true;
  auto zero_to = [&](std::size_t end) {
    for (int f = 0; f < NS; ++f) std::fill(S + f * stride + next, S + f * stride + end, 0.0);
  };
  // Cells at .. at + count - 1 are written next: zero those skipped since the last, and
  // check the order.
  auto claim = [&](std::size_t at, std::size_t count) {
    if (at > next) zero_to(at);
    in_order &= at >= next;
    next = at + count;
  };
  std::size_t q = 0;
  while (q < n) {
    const int c = cell[q];
    // The usual case at kLanes particles per cell: cells c, c+1, ... each hold exactly
    // one whole vector from q on. Two to four such go together: their lane sums by one
    // transposing sum4 a field, stored for four cells at once. The zeros stored for the
    // cells not taken are overwritten next, as every cell after is written in order (and
    // stay inside the row: c + 3 lies at most two cells past the grid, in the pads).
    // Where cells keep their particles this replaces four lane sums and 20 single stores
    // by five sum4; particles crossing cell faces leave the rest to the runs below.
    if (q + 4 * K <= n) {
      // How many of cells c .. c+3 hold exactly the next vectors: all four (one test of
      // the 4 kLanes cells against c, c+1, c+2, c+3), or else counted one by one.
      int good = 4;
      if (!simd::all(d, hn::And(hn::And(simd::cells_equal(d, cell + q, c), simd::cells_equal(d, cell + q + K, c + 1)),
                                hn::And(simd::cells_equal(d, cell + q + 2 * K, c + 2),
                                        simd::cells_equal(d, cell + q + 3 * K, c + 3)))) ||
          cell[q + 4 * K] == c + 3)
        for (good = 0; good < 4; ++good) {
          const std::size_t at = q + static_cast<std::size_t>(good) * K;
          if (!simd::all(d, simd::cells_equal(d, cell + at, c + good)) || cell[at + K] == c + good) break;
        }
      if (good >= 2) {
        vdouble b[4][NS];
        for (int g = 0; g < 4; ++g) {
          if (g < good) {
            vfields(q + static_cast<std::size_t>(g) * K, b[g]);
          } else {
            for (int f = 0; f < NS; ++f) b[g][f] = hn::Zero(d);
          }
        }
        const std::size_t at = static_cast<std::size_t>(c) + kPad;
        claim(at, static_cast<std::size_t>(good));
        for (int f = 0; f < NS; ++f) {
          const vdouble col[4] = {b[0][f], b[1][f], b[2][f], b[3][f]};
          simd::sum4(col, S + f * stride + at);
        }
        q += static_cast<std::size_t>(good) * K;
        continue;
      }
    }
    vdouble a[4 * NG];
    for (vdouble& e : a) e = hn::Zero(d);
    double r[4 * NG];
    bool tail = false;  // the run reaches the last vector's worth of particles
    for (;;) {
      if (q + K > n) {
        tail = true;
        break;
      }
      // In order, the particles of cell c are a prefix of the vector: all of it, or
      // `same` of them (the rest masked off).
      const auto in_c = simd::cells_equal(d, cell + q, c);
      vdouble b[NS];
      vfields(q, b);
      if (simd::all(d, in_c)) {
        for (int f = 0; f < NS; ++f) a[f] += b[f];
        q += K;
        if (cell[q] != c) break;  // cell[n] = -1
        continue;
      }
      const int same = simd::first_false(d, in_c);
      const auto keep = hn::FirstN(d, static_cast<std::size_t>(same));
      for (int f = 0; f < NS; ++f) a[f] += hn::IfThenElseZero(keep, b[f]);
      q += static_cast<std::size_t>(same);
      break;
    }
    for (int g = 0; g < NS / 4; ++g) simd::sum4(a + 4 * g, r + 4 * g);
    for (int f = NS / 4 * 4; f < NS; ++f) r[f] = simd::sum(a[f]);
    for (; tail && cell[q] == c; ++q) {  // cell[n] = -1 ends the last run
      double b[NS];
      sfields(q, b);
      for (int f = 0; f < NS; ++f) r[f] += b[f];
    }
    const std::size_t at = static_cast<std::size_t>(c) + kPad;
    claim(at, 1);
    for (int f = 0; f < NS; ++f) S[f * stride + at] = r[f];
  }
  zero_to(stride);
  return in_order;
}

// Pass 2 as a whole: by runs (ordered_sums) where the particles were in cell order at the
// last step, so that pass 1 need not test it (locate_all's check_order); where they are
// not, or ordered_sums finds they no longer are, particle by particle (cell_sums) with
// the same per-particle fields. Sets lc.ordered. vfields(q, o) is generic in the vector
// type of o: ordered_sums takes four lanes where the cells hold four particles or more on
// average, and two where fewer: there a vector of four would straddle cells, half its
// lanes masked off and every cell paying its own lane sums (at two particles a cell the
// four-lane sums made mpm 1.4x slower than two-lane ones; docs/performance.md, 2026-12-01).
template <int NS, class VFields, class SFields>
void per_cell_sums(LinearCells& lc, std::size_t n, std::size_t stride, double* S, VFields vfields,
                   SFields sfields) {
  const std::size_t cells = stride - 2 * kPad;
  if (lc.ordered)
    lc.ordered = n >= 4 * cells ? ordered_sums<NS>(D4(), lc.cell.data(), n, stride, S, vfields, sfields)
                                : ordered_sums<NS>(hn::CappedTag<double, 2>(), lc.cell.data(), n, stride, S, vfields,
                                                   sfields);
  if (!lc.ordered) cell_sums<NS>(lc.cell.data(), n, stride, S, sfields);
}

// Pass 3, mass and momentum: node i takes (sum m - sum m f) of cell i and sum m f of
// cell i-1 (S = 1 - f, f). Written, not accumulated: no fill, no chain through memory.
// With Force (mpm), in the same loop the force: +V sigma/dx from cell i and -V sigma/dx
// from cell i-1 (G = -1/dx, +1/dx), `scale` being 1/dx where the sums leave it out.
template <bool Force = false>
void node_mass_momentum(const double* __restrict S, std::size_t stride, int cells, Grid<1>& g,
                        double scale = 0.0) {
  const double* __restrict S0 = S + kPad;
  const double* __restrict S1 = S0 + stride;
  const double* __restrict S2 = S1 + stride;
  const double* __restrict S3 = S2 + stride;
  const double* __restrict S4 = S3 + stride;
  double* __restrict M = g.mass.data() + Grid<1>::ghost;
  double* __restrict P = g.momentum[0].data() + Grid<1>::ghost;
  double* __restrict F = g.force[0].data() + Grid<1>::ghost;
#pragma omp simd
  for (int c = 0; c <= cells; ++c) {
    M[c] = S1[c - 1] + (S0[c] - S1[c]);
    P[c] = S3[c - 1] + (S2[c] - S3[c]);
    if constexpr (Force) F[c] = scale * (S4[c] - S4[c - 1]);
  }
  g.mass.front() = g.mass.back() = 0.0;
  g.momentum[0].front() = g.momentum[0].back() = 0.0;
  if constexpr (Force) g.force[0].front() = g.force[0].back() = 0.0;
}

// The DDMP operator D (eq. 3.31), kept per node storage index.
void ddmp_table(const Grid<1>& g, LinearCells& lc) {
  if (lc.ddmp_d_left.size() == g.storage) return;
  DdmpTable t(g);
  lc.ddmp_d_left = t.dm, lc.ddmp_d_centre = t.d0, lc.ddmp_d_right = t.dp;
}



// DDMP weights of every particle: W[0..2] = alpha, (1-alpha)(1-f), (1-alpha) f at the
// particle (as ddmp_alpha and add_ddmp_gradient), a vector at a time.
[[gnu::noinline]] void ddmp_weights(std::size_t n, const double* __restrict frac, double* __restrict W) {
  const DFull d;
  constexpr int K = simd::kLanes<DFull>;
  const hn::Vec<DFull> one = hn::Set(d, 1.0);
  std::size_t q = 0;
  for (; q + K <= n; q += K) {
    const hn::Vec<DFull> f = simd::load(d, frac + q), a = simd::alpha(f), b = one - a;
    simd::store(W + q, a), simd::store(W + n + q, b * (one - f)), simd::store(W + 2 * n + q, b * f);
  }
  for (; q < n; ++q) {
    const double f = frac[q], a = ddmp_alpha(f), b = 1.0 - a;
    W[q] = a, W[n + q] = b * (1.0 - f), W[2 * n + q] = b * f;
  }
}

}  // namespace

void p2g_linear(const Grid<1>&, const Particles<1>& p, bool reference_volume,
                bool no_viscous_pressure, LinearCells& lc, Grid<1>& g) {
  const int cells = g.cells[0];
  locate_all(g, p, lc, !lc.ordered);  // the order: per_cell_sums
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
  // The force field: V (sigma - q) G, with q left out without viscosity and G (1/dx)
  // applied per node where every particle is inside.
  auto sums = [&]<bool Inside, bool Viscous>() {
    per_cell_sums<5>(
        lc, n, stride, S,
        [&](std::size_t q, auto* o) {
          using V = std::remove_pointer_t<decltype(o)>;
          auto load = [](const double* at) { return simd::load(hn::DFromV<V>(), at); };
          mass_fields(load(m + q), load(v + q), load(frac + q), o);
          const V e = load(vol + q) * (Viscous ? load(sig + q) - load(qv + q) : load(sig + q));
          o[4] = Inside ? e : e * load(grad + q);
        },
        [&](std::size_t q, double* o) {
          mass_fields(m[q], v[q], frac[q], o);
          const double e = vol[q] * (Viscous ? sig[q] - qv[q] : sig[q]);
          o[4] = Inside ? e : e * grad[q];
        });
  };
  if (plain) sums.template operator()<true, false>();
  else if (no_viscous_pressure) sums.template operator()<false, false>();
  else sums.template operator()<false, true>();
  node_mass_momentum<true>(S, stride, cells, g, plain ? g.inv_dx[0] : 1.0);
}

namespace {

// Per-cell node values for g2p: dv at the left node and its jump, and the same for the
// velocity v^{n+1/2} or v^L that moves the particle and gives grad v.
void cell_tables(const Grid<1>& g, LinearCells& lc, bool midpoint) {
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const int cells = g.cells[0];
  const double* __restrict VL = g.velocity_L[0].data() + Grid<1>::ghost;
  const double* __restrict VN = g.velocity[0].data() + Grid<1>::ghost;
  // Padded: g2p_ordered loads a vector's worth (up to eight) from any cell on.
  lc.dv_left.resize(cells + 8);
  lc.dv_jump.resize(cells + 8);
  lc.vmove_left.resize(cells + 8);
  lc.vmove_jump.resize(cells + 8);
  double* __restrict d0 = lc.dv_left.data();
  double* __restrict dd = lc.dv_jump.data();
  double* __restrict g0 = lc.vmove_left.data();
  double* __restrict dg = lc.vmove_jump.data();
#pragma omp simd
  for (int c = 0; c < cells; ++c) {
    const double a = VL[c] - VN[c], b = VL[c + 1] - VN[c + 1];
    const double u = wl * VL[c] + wn * VN[c], w = wl * VL[c + 1] + wn * VN[c + 1];
    d0[c] = a, dd[c] = b - a, g0[c] = u, dg[c] = w - u;
  }
}

}  // namespace

namespace {

// What finish() does after g2p for a linear elastic solid without viscosity, for particle
// q (T = double) or the vector of particles from q on (T = vdouble), given their grad v,
// L: V and, with Length, the domain length *= 1 + dt L; eps += dt L (0.5 (L + L) exactly);
// sigma = E eps. Returns V sigma as it was (over V0 for small strain), which times L is
// the stress work rate with the stress of the forces (eq. 4.11).
struct ElasticFields {
  double* V;
  const double* V0;
  double* eps;
  double* sig;
  double* len;
  explicit ElasticFields(Particles<1>& p)
      : V(p.volume.data()), V0(p.volume0.data()), eps(p.strain[0].data()), sig(p.stress[0].data()),
        len(p.length[0].data()) {}
};
template <bool SmallStrain, bool Length, class T>
[[gnu::always_inline]] inline T elastic_update(const ElasticFields& a, std::size_t q, T L, double dt, double E) {
  using simd::fmadd;
  using simd::load_as;
  const T vdt = simd::splat_as<T>(dt), grow = fmadd(vdt, L, simd::splat_as<T>(1.0));
  const T V = load_as<T>(a.V + q), Vs = (SmallStrain ? load_as<T>(a.V0 + q) : V) * load_as<T>(a.sig + q);
  simd::store(a.V + q, V * grow);
  if constexpr (Length) simd::store(a.len + q, load_as<T>(a.len + q) * grow);
  T e = load_as<T>(a.eps + q);
  const T sig = elastic_1d(e, L, vdt, simd::splat_as<T>(E), [](T x, T y, T z) { return fmadd(x, y, z); });
  simd::store(a.eps + q, e);
  simd::store(a.sig + q, sig);
  return Vs;
}

// The per-cell g2p tables at every particle (pc[k * n + q] = table_k[cell[q]]), for the
// portable kernel (g2p_ordered reads the tables directly).
void expand_cells(LinearCells& lc, std::size_t n) {
  lc.at_particle.resize(4 * n);
  const double* tab[4] = {lc.dv_left.data(), lc.dv_jump.data(), lc.vmove_left.data(), lc.vmove_jump.data()};
  const int* __restrict cell = lc.cell.data();
  double* __restrict out = lc.at_particle.data();
  for (std::size_t q = 0; q < n; ++q)
    for (int k = 0; k < 4; ++k) out[k * n + q] = tab[k][cell[q]];
}

// g2p from the expanded tables: v, x and grad v; with Update, the elastic update in the
// same pass (its stress work in `work`). The choices are fixed at compile time so that
// the loop vectorises.
template <bool Update, bool SmallStrain>
[[gnu::noinline]] double g2p_expanded(const LinearCells& lc, double dt, double dtm, double E, Particles<1>& p,
                                      double& work) {
  const std::size_t n = p.size();
  const double* __restrict d0 = lc.at_particle.data();  // the cell's tables, at each particle
  const double* __restrict dd = d0 + n;
  const double* __restrict g0 = dd + n;
  const double* __restrict dg = g0 + n;
  const double* __restrict frac = lc.frac.data();
  const double* __restrict grad = lc.grad.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  const ElasticFields el(p);
  double check = 0.0, w = 0.0;
#pragma omp simd reduction(+ : check, w)
  for (std::size_t q = 0; q < n; ++q) {
    const double f = frac[q];
    const double vq = v[q] + (d0[q] + f * dd[q]);
    const double xq = x[q] + dtm * (g0[q] + f * dg[q]);
    const double Lq = dg[q] * grad[q];
    v[q] = vq, x[q] = xq, L[q] = Lq;
    check += vq + xq;
    if constexpr (Update) w += elastic_update<SmallStrain, false>(el, q, Lq, dt, E) * Lq;
  }
  work = w;
  return check;
}

// g2p_expanded without the expanded tables, for particles in cell order: a vector of
// particles whose cells lie within a vector's width of the first take their cells' table
// values by one load and a permute each, in registers. Other blocks, and the last, go
// particle by particle through the same arithmetic. Inside: every gradient is 1/dx.
template <bool Update, bool SmallStrain, bool Inside>
[[gnu::noinline]] double g2p_ordered(const LinearCells& lc, double dt, double dtm, double E, double inv,
                                     Particles<1>& p, double& work) {
  using simd::fmadd;
  const D4 d;
  using vdouble = hn::Vec<D4>;
  constexpr int K = simd::kLanes<D4>;
  const std::size_t n = p.size();
  const double* __restrict T0 = lc.dv_left.data();
  const double* __restrict T1 = lc.dv_jump.data();
  const double* __restrict T2 = lc.vmove_left.data();
  const double* __restrict T3 = lc.vmove_jump.data();
  const int* __restrict cell = lc.cell.data();
  const double* __restrict frac = lc.frac.data();
  const double* __restrict grad = lc.grad.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  const ElasticFields el(p);
  const vdouble vdtm = hn::Set(d, dtm);
  vdouble check = hn::Zero(d), w = hn::Zero(d);
  double check1 = 0.0, w1 = 0.0;
  auto one_particle = [&](std::size_t q) {
    const int c = cell[q];
    const double f = frac[q];
    const double vq = v[q] + fmadd(f, T1[c], T0[c]);
    const double xq = fmadd(dtm, fmadd(f, T3[c], T2[c]), x[q]);
    const double Lq = T3[c] * grad[q];
    v[q] = vq, x[q] = xq, L[q] = Lq;
    check1 += vq + xq;
    if constexpr (Update) w1 = fmadd(elastic_update<SmallStrain, false>(el, q, Lq, dt, E), Lq, w1);
  };
  std::size_t q = 0;
  for (; q + K <= n; q += K) {
    const int c0 = cell[q];
    if (cell[q + K - 1] - c0 >= K) {
      for (std::size_t r = q; r < q + K; ++r) one_particle(r);
      continue;
    }
    const simd::Lookup<D4> idx = simd::lookup_index(d, cell + q, c0);
    const vdouble dg = simd::lookup(d, T3 + c0, idx);
    const vdouble f = simd::load(d, frac + q);
    const vdouble vq = simd::load(d, v + q) + fmadd(f, simd::lookup(d, T1 + c0, idx), simd::lookup(d, T0 + c0, idx));
    const vdouble xq = fmadd(vdtm, fmadd(f, dg, simd::lookup(d, T2 + c0, idx)), simd::load(d, x + q));
    const vdouble Lq = dg * (Inside ? hn::Set(d, inv) : simd::load(d, grad + q));
    simd::store(v + q, vq), simd::store(x + q, xq), simd::store(L + q, Lq);
    check += vq + xq;
    if constexpr (Update) w = fmadd(elastic_update<SmallStrain, false>(el, q, Lq, dt, E), Lq, w);
  }
  for (; q < n; ++q) one_particle(q);
  work = w1 + simd::sum(w);
  return check1 + simd::sum(check);
}


}  // namespace

double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                  Particles<1>& p, ElasticUpdate* update) {
  cell_tables(g, lc, midpoint);
  const double dtm = move ? dt : 0.0, inv = g.inv_dx[0];
  const double E = update ? update->youngs_modulus : 0.0;
  double w = 0.0;
  auto run = [&]<bool Update, bool SmallStrain>() {
    if (lc.ordered)
      return lc.inside ? g2p_ordered<Update, SmallStrain, true>(lc, dt, dtm, E, inv, p, w)
                       : g2p_ordered<Update, SmallStrain, false>(lc, dt, dtm, E, inv, p, w);
    expand_cells(lc, p.size());
    return g2p_expanded<Update, SmallStrain>(lc, dt, dtm, E, p, w);
  };
  if (!update) return run.template operator()<false, false>();
  const double check = update->small_strain ? run.template operator()<true, true>()
                                            : run.template operator()<true, false>();
  update->stress_work += dt * w;
  update->done = true;
  return check;
}

void p2g_ddmp(const Grid<1>&, const Particles<1>& p, bool reference_volume, int subpoints,
              LinearCells& lc, Grid<1>& g) {
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  const double top = cells, inv = g.inv_dx[0], x0 = g.lower[0];
  const bool sub = subpoints > 0;
  ddmp_table(g, lc);
  locate_all(g, p, lc, !lc.ordered);  // the order: per_cell_sums
  constexpr int nw = 3;  // weights per particle (sub-points in other cells: lc.ddmp_w_next)
  lc.ddmp_w.resize(nw * n);
  const int* __restrict cell = lc.cell.data();
  const double* __restrict x = p.x[0].data();
  if (!sub) {
    lc.mixed.clear();
    lc.stray.clear();
    ddmp_weights(n, lc.frac.data(), lc.ddmp_w.data());
  } else {
    lc.ddmp_w_next.resize(4 * n);
    fused::subpoint_weights(n, x, p.length[0].data(), cell, x0, inv, top, subpoints, lc.ddmp_w.data(), lc.ddmp_w_next.data(),
                     lc.mixed, lc.stray);
  }
  // Pass 2 over m, m f, m v, m v f and V sigma times each weight.
  const std::size_t stride = static_cast<std::size_t>(cells) + 2 * kPad;
  const int ns = 4 + nw;
  lc.sums.resize(ns * stride);
  const double* __restrict vol = reference_volume ? p.volume0.data() : p.volume.data();
  const double* __restrict sig = p.stress[0].data();
  const double* __restrict qv = p.viscous_pressure.data();
  const double* __restrict W = lc.ddmp_w.data();
  const double* __restrict m = p.mass.data();
  const double* __restrict v = p.v[0].data();
  const double* __restrict frac = lc.frac.data();
  double* S = lc.sums.data();
  per_cell_sums<7>(
      lc, n, stride, S,
      [&](std::size_t q, auto* o) {
        using V = std::remove_pointer_t<decltype(o)>;
        auto load = [](const double* at) { return simd::load(hn::DFromV<V>(), at); };
        mass_fields(load(m + q), load(v + q), load(frac + q), o);
        const V vs = load(vol + q) * (load(sig + q) - load(qv + q));
        for (int k = 0; k < nw; ++k) o[4 + k] = vs * load(W + k * n + q);
      },
      [&](std::size_t q, double* o) {
        mass_fields(m[q], v[q], frac[q], o);
        const double vs = vol[q] * (sig[q] - qv[q]);
        for (int k = 0; k < nw; ++k) o[4 + k] = vs * W[k * n + q];
      });
  node_mass_momentum(S, stride, cells, g);
  // f_i = -sum_p V sigma Gbar_ip: the alpha part gives +-V sigma alpha/dx at the two
  // nodes of the point's cell; the rest is -sum_j D_ji Q_j with Q_j the hat-weighted
  // nodal sum of V sigma (1 - alpha) (eq. 3.31). Per cell: SA[c]; per node: Q[j].
  const double* __restrict F0 = S + 4 * stride + kPad;  // force fields by particle cell
  lc.scratch_sums.resize(cells + 2);
  lc.scratch_dv.resize(g.storage + 8);  // padded: eight-wide loads from any node
  double* __restrict SA = lc.scratch_sums.data() + 1;                // cells -1 .. cells
  double* __restrict Q = lc.scratch_dv.data() + Grid<1>::ghost;   // nodes -1 .. cells + 1
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
  const double* __restrict Wx = lc.ddmp_w_next.data();
  for (const int q : lc.mixed) {
    const int c = cell[q];
    const double vs = vol[q] * (sig[q] - qv[q]);
    SA[c - 1] += vs * Wx[q], SA[c + 1] += vs * Wx[n + q];
    Q[c - 1] += vs * Wx[2 * n + q], Q[c + 2] += vs * Wx[3 * n + q];
  }
  const double* __restrict dm = lc.ddmp_d_left.data() + Grid<1>::ghost;
  const double* __restrict dc = lc.ddmp_d_centre.data() + Grid<1>::ghost;
  const double* __restrict dp = lc.ddmp_d_right.data() + Grid<1>::ghost;
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
// nodal gradients Dv (eq. 3.31), with sub-points (Sub) their parts in the neighbouring
// cells too (Wx; sub-points further away are added by the caller). With Update, the
// elastic update in the same pass (elastic_update, the domain length too with sub-points),
// its stress work in `work`.
template <bool Sub, bool Update, bool SmallStrain>
[[gnu::noinline]] double ddmp_g2p_kernel(const LinearCells& lc, std::size_t n, double dt, double dtm,
                                         double inv, double E, Particles<1>& p, double& work) {
  using simd::fmadd;
  using simd::store;
  const D4 d;
  using vdouble = hn::Vec<D4>;
  constexpr int K = simd::kLanes<D4>;
  auto load = [d](const double* at) { return simd::load(d, at); };
  const double* __restrict d0 = lc.dv_left.data();
  const double* __restrict dd = lc.dv_jump.data();
  const double* __restrict g0 = lc.vmove_left.data();
  const double* __restrict dg = lc.vmove_jump.data();
  const double* __restrict dgp = lc.scratch_sums.data() + 1;               // dg with a zero each side
  const double* __restrict Dn = lc.scratch_dv.data() + Grid<1>::ghost;  // by node, -1 .. cells + 1
  const int* __restrict cell = lc.cell.data();
  const double* __restrict frac = lc.frac.data();
  const double* __restrict W = lc.ddmp_w.data();
  const double* __restrict Wx = lc.ddmp_w_next.data();
  double* __restrict x = p.x[0].data();
  double* __restrict v = p.v[0].data();
  double* __restrict L = p.grad_v[0].data();
  const ElasticFields el(p);
  double check = 0.0, w = 0.0;
  auto one_particle = [&](std::size_t q) {
    const int c = cell[q];
    const double f = frac[q];
    const double vq = v[q] + (d0[c] + f * dd[c]);
    const double xq = x[q] + dtm * (g0[c] + f * dg[c]);
    v[q] = vq, x[q] = xq;
    double Lq = W[q] * inv * dg[c] + W[n + q] * Dn[c] + W[2 * n + q] * Dn[c + 1];
    if constexpr (Sub)
      Lq += inv * (Wx[q] * dgp[c - 1] + Wx[n + q] * dgp[c + 1]) +
            (Wx[2 * n + q] * Dn[c - 1] + Wx[3 * n + q] * Dn[c + 2]);
    L[q] = Lq;
    check += vq + xq;
    if constexpr (Update) w = fmadd(elastic_update<SmallStrain, Sub>(el, q, Lq, dt, E), Lq, w);
  };
  std::size_t q0 = 0;
  // In cell order: a vector of particles whose cells lie within its width of the first
  // take the tables by one load and a permute each (as g2p_ordered).
  if (lc.ordered) {
    const vdouble vinv = hn::Set(d, inv), vdtm = hn::Set(d, dtm);
    vdouble vcheck = hn::Zero(d), vw = hn::Zero(d);
    for (; q0 + K <= n; q0 += K) {
      const int c0 = cell[q0];
      if (cell[q0 + K - 1] - c0 >= K) break;  // the rest one by one
      const simd::Lookup<D4> idx = simd::lookup_index(d, cell + q0, c0);
      auto at = [&](const double* t) { return simd::lookup(d, t + c0, idx); };
      const vdouble f = load(frac + q0);
      const vdouble vq = load(v + q0) + fmadd(f, at(dd), at(d0));
      const vdouble dgc = at(dg);
      const vdouble xq = fmadd(vdtm, fmadd(f, dgc, at(g0)), load(x + q0));
      store(v + q0, vq), store(x + q0, xq);
      vdouble Lq = fmadd(load(W + q0), vinv * dgc, fmadd(load(W + n + q0), at(Dn), load(W + 2 * n + q0) * at(Dn + 1)));
      if constexpr (Sub)
        Lq += vinv * (load(Wx + q0) * at(dgp - 1) + load(Wx + n + q0) * at(dgp + 1)) +
              (load(Wx + 2 * n + q0) * at(Dn - 1) + load(Wx + 3 * n + q0) * at(Dn + 2));
      store(L + q0, Lq);
      vcheck += vq + xq;
      if constexpr (Update) vw = fmadd(elastic_update<SmallStrain, Sub>(el, q0, Lq, dt, E), Lq, vw);
    }
    check += simd::sum(vcheck);
    w += simd::sum(vw);
  }
  for (std::size_t q = q0; q < n; ++q) one_particle(q);
  work = w;
  return check;
}

}  // namespace

double g2p_ddmp(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint,
                int subpoints, Particles<1>& p, ElasticUpdate* update) {
  cell_tables(g, lc, midpoint);
  const std::size_t n = p.size();
  const int cells = g.cells[0];
  const double wl = midpoint ? 0.5 : 1.0, wn = midpoint ? 0.5 : 0.0;
  const double top = cells, inv = g.inv_dx[0], x0 = g.lower[0];
  // Nodal gradient of the velocity that gives grad v: Dv_j = sum_i D_ji vg_i (ghosts 0).
  grow(lc.val, g.storage);  // free after p2g: scratch
  lc.scratch_dv.resize(g.storage + 8);  // padded: eight-wide loads from any node
  const double* __restrict VL = g.velocity_L[0].data();
  const double* __restrict VN = g.velocity[0].data();
  double* __restrict vg = lc.val.data();
#pragma omp simd
  for (std::size_t i = 0; i < g.storage; ++i) vg[i] = wl * VL[i] + wn * VN[i];
  const double* __restrict dm = lc.ddmp_d_left.data();
  const double* __restrict dc = lc.ddmp_d_centre.data();
  const double* __restrict dp = lc.ddmp_d_right.data();
  double* __restrict Dv = lc.scratch_dv.data();
  const std::size_t last = g.storage - 1;
  Dv[0] = Dv[last] = 0.0;
#pragma omp simd
  for (std::size_t j = 1; j < last; ++j)
    Dv[j] = dm[j] * vg[j - 1] + dc[j] * vg[j] + dp[j] * vg[j + 1];
  // dg with a zero pad each side (and eight-wide loads from any cell), for sub-points in
  // the neighbouring cells.
  lc.scratch_sums.assign(static_cast<std::size_t>(cells) + 10, 0.0);
  std::copy(lc.vmove_jump.begin(), lc.vmove_jump.begin() + cells, lc.scratch_sums.begin() + 1);
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
      e += sw.a * inv * lc.vmove_jump[sw.c] + sw.b0 * Dn[sw.c] + sw.b1 * Dn[sw.c + 1];
    }
    extra[k] = e / subpoints;
  }
  const double dtm = move ? dt : 0.0;
  // The elastic update in the same pass unless strays add to grad v afterwards.
  const bool fused = update && lc.stray.empty();
  const double E = update ? update->youngs_modulus : 0.0;
  double w = 0.0;
  auto kernel = [&]<bool Sub>() {
    if (!fused) return ddmp_g2p_kernel<Sub, false, false>(lc, n, dt, dtm, inv, E, p, w);
    return update->small_strain ? ddmp_g2p_kernel<Sub, true, true>(lc, n, dt, dtm, inv, E, p, w)
                                : ddmp_g2p_kernel<Sub, true, false>(lc, n, dt, dtm, inv, E, p, w);
  };
  const double check = subpoints > 0 ? kernel.template operator()<true>() : kernel.template operator()<false>();
  if (fused) {
    update->stress_work += dt * w;
    update->done = true;
  }
  double* L = p.grad_v[0].data();
  for (std::size_t k = 0; k < lc.stray.size(); ++k) L[lc.stray[k]] += extra[k];
  return check;
}

// The path this copy of the kernels is, for isa_dispatched.
int64_t dispatched_target() { return HWY_TARGET; }

}  // namespace mpmx::mpm::shape::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::mpm::shape {

HWY_EXPORT(p2g_linear);
HWY_EXPORT(g2p_linear);
HWY_EXPORT(p2g_ddmp);
HWY_EXPORT(g2p_ddmp);
HWY_EXPORT(dispatched_target);

int64_t fused::dispatched_target() {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(dispatched_target)();
}

std::string isa_dispatched() { return isa_name(fused::dispatched_target()); }

void p2g_linear(const Grid<1>& g0, const Particles<1>& p, bool reference_volume, bool no_viscous_pressure,
                LinearCells& lc, Grid<1>& g) {
  isa_prepare();
  HWY_DYNAMIC_DISPATCH(p2g_linear)(g0, p, reference_volume, no_viscous_pressure, lc, g);
}

double g2p_linear(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint, Particles<1>& p,
                  ElasticUpdate* update) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(g2p_linear)(g, lc, dt, move, midpoint, p, update);
}

void p2g_ddmp(const Grid<1>& g0, const Particles<1>& p, bool reference_volume, int subpoints, LinearCells& lc,
              Grid<1>& g) {
  isa_prepare();
  HWY_DYNAMIC_DISPATCH(p2g_ddmp)(g0, p, reference_volume, subpoints, lc, g);
}

double g2p_ddmp(const Grid<1>& g, LinearCells& lc, double dt, bool move, bool midpoint, int subpoints,
                Particles<1>& p, ElasticUpdate* update) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(g2p_ddmp)(g, lc, dt, move, midpoint, subpoints, p, update);
}

}  // namespace mpmx::mpm::shape
#endif  // HWY_ONCE
