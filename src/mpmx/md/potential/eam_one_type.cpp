// The one-element EAM kernel, compiled once per vector path of core/simd_targets.hpp
// (hwy/foreach_target.h includes this file again for each); the entry points at the end
// dispatch to the path the 1-D kernels take. On the scalar path the vector helpers are
// absent and the scalar loops do everything: that path is the reference the others
// match bit for bit. They do so by computing each value with the scalar loop's
// operations in its order, lane by lane, and with no fused multiply-add anywhere: this
// file is compiled with -ffp-contract=off (CMakeLists.txt), so neither the scalar loops
// nor the vector code are contracted on any path, in any build.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the paths to compile
// clang-format on

#include "mpmx/md/potential/eam_one_type.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "mpmx/core/isa.hpp"
#include "mpmx/md/potential/tile_shares.hpp"

#ifndef MPMX_MD_EAM_ONE_TYPE_SCRATCH_
#define MPMX_MD_EAM_ONE_TYPE_SCRATCH_
namespace mpmx::md {
namespace {
// Per-thread scratch of the kernel (not part of a System's state, so thousands of
// Systems do not each carry it): the pairs inside the cutoff found by the density pass
// (entry, r then the spline offset p, 1/r, knot), reused by the force pass, and packed
// forces. A threaded call uses its calling thread's.
struct Scratch {
  std::vector<int> cut_first, cut_end, cut_k, cut_m;
  std::vector<double> cut_r, cut_ri;
  std::vector<float> cut_rf, cut_rif;
  std::vector<double> f4;
  // The tiled form's: per tile entry its position, density, F', energy and virial
  // shares (f4 holds its forces); per tile the pair energy and virial; per atom F.
  std::vector<double> tile_q, tile_rho, tile_fp, tile_e, tile_w, tile_sums, embed_atom;
};
thread_local Scratch scratch;
}  // namespace
}  // namespace mpmx::md
#endif

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "mpmx/md/potential/eam_one_type.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace mpmx::md::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

namespace {

#if HWY_TARGET != HWY_SCALAR
// Positions (x, y, z, 0 per atom) and forces go four doubles at most a vector: a wider
// one would hold two atoms, to be split again (and AVX-512 would gain nothing on AVX2).
// The spline arithmetic goes kG pairs a vector (DR), each knot record one load per pair:
// in float lanes, eight on the AVX2 path, four elsewhere (on AVX-512 eight were no faster
// than four, and slower than AVX2's eight: docs/performance.md); in four double lanes
// where they fit (not on the 128-bit path: the scalar loop does it there).
using DD = hn::CappedTag<double, 4>;
using VD = hn::Vec<DD>;
constexpr int kD = static_cast<int>(hn::MaxLanes(DD()));
static_assert(kD == 2 || kD == 4);
template <class Real, int G>
using DR = hn::CappedTag<Real, G>;
// The lanes of the spline vectors; at eight, four at a time follow (so that the scalar
// loop is left three pairs at most).
template <class Real>
constexpr int kG = std::is_same_v<Real, float> && HWY_TARGET == HWY_AVX2 ? 8 : 4;
// Whether the path has vectors of G lanes of Real.
template <class Real, int G>
constexpr bool kHas = static_cast<int>(hn::MaxLanes(DR<Real, G>())) == G;

// The knot records of pairs l and l + 4 (at eight lanes), from coefficient `off` on: one
// row of four coefficients (in each 128-bit block at eight float lanes).
template <class D, class T>
HWY_INLINE hn::Vec<D> row(D d, const T* const* c, int l, int off) {
  if constexpr (hn::MaxLanes(D()) == 8) {
    const hn::Half<D> h;
    return hn::Combine(d, hn::LoadU(h, c[l + 4] + off), hn::LoadU(h, c[l] + off));
  } else {
    return hn::LoadU(d, c[l] + off);
  }
}

// Rows r0..r3 (four coefficients of four pairs, per 128-bit block at float lanes) to
// columns (one coefficient, the pairs in order).
template <class V>
HWY_INLINE void transpose4(V& r0, V& r1, V& r2, V& r3) {
  const hn::DFromV<V> d;
  if constexpr (sizeof(hn::TFromV<V>) == 4) {  // by 32-bit interleaves only: t0 = a0 c0 a1 c1
    const V t0 = hn::InterleaveLower(d, r0, r2), t1 = hn::InterleaveLower(d, r1, r3);
    const V t2 = hn::InterleaveUpper(d, r0, r2), t3 = hn::InterleaveUpper(d, r1, r3);
    r0 = hn::InterleaveLower(d, t0, t1), r1 = hn::InterleaveUpper(d, t0, t1);
    r2 = hn::InterleaveLower(d, t2, t3), r3 = hn::InterleaveUpper(d, t2, t3);
  } else {  // four doubles: t0 = a0 b0 | a2 b2
    const V t0 = hn::InterleaveLower(d, r0, r1), t1 = hn::InterleaveLower(d, r2, r3);
    const V t2 = hn::InterleaveUpper(d, r0, r1), t3 = hn::InterleaveUpper(d, r2, r3);
    r0 = hn::ConcatLowerLower(d, t1, t0), r1 = hn::ConcatLowerLower(d, t3, t2);
    r2 = hn::ConcatUpperUpper(d, t1, t0), r3 = hn::ConcatUpperUpper(d, t3, t2);
  }
}

// The lanes of DR as doubles, in order: a conversion per four where four doubles fit a
// vector.
template <class V>
HWY_INLINE void to_double(V v, double* out) {
  using T = hn::TFromV<V>;
  const hn::DFromV<V> d;
  constexpr int G = static_cast<int>(hn::MaxLanes(d));
  if constexpr (std::is_same_v<T, double>) {
    hn::StoreU(v, d, out);
  } else if constexpr (kD == 4 && G == 8) {
    const hn::Half<decltype(d)> h;
    hn::StoreU(hn::PromoteTo(DD(), hn::LowerHalf(h, v)), DD(), out);
    hn::StoreU(hn::PromoteTo(DD(), hn::UpperHalf(h, v)), DD(), out + 4);
  } else if constexpr (kD == 4) {
    hn::StoreU(hn::PromoteTo(DD(), v), DD(), out);
  } else {
    T t[G];
    hn::StoreU(v, d, t);
    for (int l = 0; l < G; ++l) out[l] = t[l];
  }
}

// Lane choices for a 4-bit mask: the set lanes first, in order, as 32-bit lane indices
// (and as pairs of them, for 64-bit lanes). A static table: Highway's Compress builds its
// table on the stack at each call.
struct Compact {
  alignas(16) int32_t i4[16][4];
  alignas(32) int32_t i8[16][8];
  Compact() {
    for (int m = 0; m < 16; ++m) {
      int n = 0;
      for (int l = 0; l < 4; ++l)
        if (m >> l & 1) i4[m][n] = l, i8[m][2 * n] = 2 * l, i8[m][2 * n + 1] = 2 * l + 1, ++n;
      for (; n < 4; ++n) i4[m][n] = 0, i8[m][2 * n] = 0, i8[m][2 * n + 1] = 1;
    }
  }
};
const Compact kCompact;

// The filter four candidates at a time (on a path with four double lanes; the 128-bit
// path leaves it to the scalar loop, itself branch-free): r^2 from the positions (one load
// per atom, transposed in registers), and the candidates within the cut-off written
// packed by a permute (no branch: the in/out decision is unpredictable). Returns the
// first candidate left for the scalar loop.
template <class Real>
int filter(const double* __restrict q, int i, const int* __restrict list, int s, int end, double cutsq,
           int* __restrict ck, Real* __restrict cr, int& npair) {
  if constexpr (kD == 4) {
    const DD d;
    const hn::Rebind<int32_t, DD> di;
    const hn::Rebind<float, DD> df;
    const hn::Repartition<int32_t, DD> d32;
    const VD cut = hn::Set(d, cutsq), xi = hn::LoadU(d, q + 4 * i);
    for (; s + 4 <= end; s += 4) {
      const VD d0 = xi - hn::LoadU(d, q + 4 * list[s]), d1 = xi - hn::LoadU(d, q + 4 * list[s + 1]);
      const VD d2 = xi - hn::LoadU(d, q + 4 * list[s + 2]), d3 = xi - hn::LoadU(d, q + 4 * list[s + 3]);
      // Within 128-bit blocks: [x0 x1 | z0 z1], [y0 y1 | 0 0], then across them.
      const VD t0 = hn::InterleaveLower(d, d0, d1), t1 = hn::InterleaveUpper(d, d0, d1);
      const VD t2 = hn::InterleaveLower(d, d2, d3), t3 = hn::InterleaveUpper(d, d2, d3);
      const VD dx = hn::ConcatLowerLower(d, t2, t0), dy = hn::ConcatLowerLower(d, t3, t1);
      const VD dz = hn::ConcatUpperUpper(d, t2, t0);
      const VD rsq = dx * dx + dy * dy + dz * dz;
      uint8_t bits[8] = {};
      hn::StoreMaskBits(d, hn::Lt(rsq, cut), bits);
      const int m = bits[0];
      hn::StoreU(hn::TableLookupLanes(hn::LoadU(di, list + s), hn::SetTableIndices(di, kCompact.i4[m])), di,
                 ck + npair);
      if constexpr (std::is_same_v<Real, double>)
        hn::StoreU(hn::BitCast(d, hn::TableLookupLanes(hn::BitCast(d32, rsq), hn::SetTableIndices(d32, kCompact.i8[m]))),
                   d, cr + npair);
      else
        hn::StoreU(hn::TableLookupLanes(hn::DemoteTo(df, rsq), hn::SetTableIndices(df, kCompact.i4[m])), df,
                   cr + npair);
      npair += static_cast<int>(hwy::PopCount(static_cast<uint64_t>(m)));
    }
  }
  return s;
}

// r and 1/r of the pairs [s, end) (packed square root and division are correctly
// rounded: the scalar operations' bits). At most 256 bits a vector. Returns the first
// pair left.
template <class Real>
int root(Real* __restrict cr, Real* __restrict cri, int s, int end) {
  const hn::CappedTag<Real, 32 / sizeof(Real)> d;
  constexpr int K = static_cast<int>(hn::MaxLanes(d));
  const auto one = hn::Set(d, Real(1));
  for (; s + K <= end; s += K) {
    const auto r = hn::Sqrt(hn::LoadU(d, cr + s));
    hn::StoreU(r, d, cr + s);
    hn::StoreU(hn::Div(one, r), d, cri + s);
  }
  return s;
}

// The density pass G pairs of atom i at a time: knot and offset in lanes (kept for the
// force pass), the knot records transposed in registers, the spline in lanes, then the
// sums in pair order. Returns the first pair left.
template <class Real, int G>
int density(const Real* __restrict rho_tab, Real rdr, int nrm1, const int* __restrict ck, Real* __restrict cr,
            int* __restrict cm, int s, int end, double* __restrict rho, double& rho_i) {
  if constexpr (kHas<Real, G>) {
    using V = hn::Vec<DR<Real, G>>;
    const DR<Real, G> d;
    const hn::Rebind<int32_t, DR<Real, G>> di;
    const V vrdr = hn::Set(d, rdr), one = hn::Set(d, Real(1));
    const auto last = hn::Set(di, nrm1);
    for (; s + G <= end; s += G) {
      V p = hn::LoadU(d, cr + s) * vrdr + one;
      // Truncation to int and back, as static_cast does.
      hn::Vec<decltype(di)> m;
      if constexpr (std::is_same_v<Real, float>)
        m = hn::Min(hn::ConvertTo(di, p), last);
      else
        m = hn::Min(hn::DemoteTo(di, p), last);
      if constexpr (std::is_same_v<Real, float>)
        p = hn::Min(one, p - hn::ConvertTo(d, m));
      else
        p = hn::Min(one, p - hn::PromoteTo(d, m));
      hn::StoreU(p, d, cr + s);
      hn::StoreU(m, di, cm + s);
      const Real* c[G];
      for (int l = 0; l < G; ++l) c[l] = rho_tab + 4 * cm[s + l];
      V c0 = row(d, c, 0, 0), c1 = row(d, c, 1, 0), c2 = row(d, c, 2, 0), c3 = row(d, c, 3, 0);
      transpose4(c0, c1, c2, c3);
      double v[G];
      to_double(((c0 * p + c1) * p + c2) * p + c3, v);
      for (int l = 0; l < G; ++l) {
        rho_i += v[l];
        rho[ck[s + l]] += v[l];
      }
    }
  }
  return s;
}

// The force pass (no per-atom tallies) G pairs of atom i at a time: the knot records
// transposed in registers (coefficients 0-3, 4-7 and, from the load at 6, 8-9), the
// spline and pair force in lanes, then each pair's force (x, y, z, 0) in double vectors,
// added to i's sum (fi, four doubles, carried in and out) and taken from k's in pair
// order. Returns the first pair left.
template <class Real, int G, bool Tally>
int force(const double* __restrict q, int i, Real fpi, const double* __restrict fpa, const Real* __restrict pair_tab,
          const int* __restrict ck, const Real* __restrict cr, const Real* __restrict cri, const int* __restrict cm,
          int s, int end, double* __restrict f, double* __restrict fi, double& epair) {
  if constexpr (kHas<Real, G>) {
    using V = hn::Vec<DR<Real, G>>;
    const DR<Real, G> d;
    const DD dd;
    constexpr int H = 4 / kD;  // vectors per atom
    VD xi[H], sum[H];
    for (int h = 0; h < H; ++h) xi[h] = hn::LoadU(dd, q + 4 * i + kD * h), sum[h] = hn::LoadU(dd, fi + kD * h);
    const V vfpi = hn::Set(d, fpi);
    for (; s + G <= end; s += G) {
      const Real* c[G];
      for (int l = 0; l < G; ++l) c[l] = pair_tab + kEamPairStride * cm[s + l];
      V a0 = row(d, c, 0, 0), a1 = row(d, c, 1, 0), a2 = row(d, c, 2, 0), a3 = row(d, c, 3, 0);
      transpose4(a0, a1, a2, a3);
      V b0 = row(d, c, 0, 4), b1 = row(d, c, 1, 4), b2 = row(d, c, 2, 4), b3 = row(d, c, 3, 4);
      transpose4(b0, b1, b2, b3);
      V e0 = row(d, c, 0, 6), e1 = row(d, c, 1, 6), e2 = row(d, c, 2, 6), e3 = row(d, c, 3, 6);
      transpose4(e0, e1, e2, e3);  // e2, e3: coefficients 8, 9
      const V p = hn::LoadU(d, cr + s), recip = hn::LoadU(d, cri + s);
      const V rhop = (a0 * p + a1) * p + a2;
      const V z2p = (a3 * p + b0) * p + b1;
      const V z2 = ((b2 * p + b3) * p + e2) * p + e3;
      const V phi = z2 * recip;
      const V phip = z2p * recip - phi * recip;
      Real fk[G];
      for (int l = 0; l < G; ++l) fk[l] = static_cast<Real>(fpa[ck[s + l]]);
      const V psip = vfpi * rhop + hn::LoadU(d, fk) * rhop + phip;
      double fpair[G];
      to_double(hn::Neg(psip) * recip, fpair);
      for (int l = 0; l < G; ++l) {
        const double* qk = q + 4 * ck[s + l];
        double* fk4 = f + 4 * ck[s + l];
        const VD fp = hn::Set(dd, fpair[l]);
        for (int h = 0; h < H; ++h) {
          const VD ff = (xi[h] - hn::LoadU(dd, qk + kD * h)) * fp;
          sum[h] = sum[h] + ff;
          hn::StoreU(hn::LoadU(dd, fk4 + kD * h) - ff, dd, fk4 + kD * h);
        }
      }
      if constexpr (Tally) {
        double e[G];
        to_double(phi, e);
        for (int l = 0; l < G; ++l) epair += e[l];
      }
    }
    for (int h = 0; h < H; ++h) hn::StoreU(sum[h], dd, fi + kD * h);
  }
  return s;
}
#endif  // HWY_TARGET != HWY_SCALAR

// The pairs inside the cutoff found by the density pass, kept for the force pass: per
// pair the partner entry, r then the spline offset p, 1/r and the knot (at the pair's
// place, packed from a given list slot on); per atom the first and one past the last.
template <class Real>
struct CutPairs {
  int* ck;
  Real* cr;
  Real* cri;
  int* cm;
  int* cbeg;
  int* cend;
};

// The density pass of atoms [0, n): entries 0..n-1 of q, their candidates in
// list[first[i] .. first[i+1]) (entries of q), the pairs packed from slot `npair` on.
// Adds each pair's density to both atoms' rho (entries of q). In blocks of atoms, so the
// pair data just written is still in cache: filter the candidates, r and 1/r in one
// contiguous sweep, then the density; knot and offset are kept for the force pass. Each
// loop starts with its vector form where the path has one and ends with the scalar loop
// (all of it on the scalar path).
template <class Real>
void density_pass(const EamOneType<Real>& t, const double* __restrict q, const int* __restrict first,
                  const int* __restrict list, int n, int npair, const CutPairs<Real>& cp, double* __restrict rho) {
  const Real* __restrict rho_tab = t.rho_tab;
  const double cutsq = t.cut * t.cut;
  const Real rdr = static_cast<Real>(t.rdr);
  const int nrm1 = t.nr - 1;
  int* __restrict ck = cp.ck;
  int* __restrict cm = cp.cm;
  Real* __restrict cr = cp.cr;
  Real* __restrict cri = cp.cri;
  constexpr int kBlock = 64;
  for (int i0 = 0; i0 < n; i0 += kBlock) {
    const int i1 = std::min(n, i0 + kBlock);
    const int start = npair;
    for (int i = i0; i < i1; ++i) {
      cp.cbeg[i] = npair;
      const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
      int s = first[i];
#if HWY_TARGET != HWY_SCALAR
      s = filter(q, i, list, s, first[i + 1], cutsq, ck, cr, npair);
#endif
      for (; s < first[i + 1]; ++s) {  // branch-free
        const int k = list[s];
        const double dx = xi - q[4 * k], dy = yi - q[4 * k + 1], dz = zi - q[4 * k + 2];
        const double rsq = dx * dx + dy * dy + dz * dz;
        ck[npair] = k;
        cr[npair] = static_cast<Real>(rsq);
        npair += rsq < cutsq;
      }
      cp.cend[i] = npair;
    }
    int s0 = start;
#if HWY_TARGET != HWY_SCALAR
    s0 = root(cr, cri, s0, npair);
#endif
    for (int s = s0; s < npair; ++s) {
      const Real r = std::sqrt(cr[s]);
      cr[s] = r;
      cri[s] = Real(1) / r;
    }
    for (int i = i0; i < i1; ++i) {
      double rho_i = 0;
      int s = cp.cbeg[i];
#if HWY_TARGET != HWY_SCALAR
      s = density<Real, kG<Real>>(rho_tab, rdr, nrm1, ck, cr, cm, s, cp.cend[i], rho, rho_i);
      if constexpr (kG<Real> == 8) s = density<Real, 4>(rho_tab, rdr, nrm1, ck, cr, cm, s, cp.cend[i], rho, rho_i);
#endif
      for (; s < cp.cend[i]; ++s) {
        const int k = ck[s];
        Real p = cr[s] * rdr + Real(1);
        const int m = std::min(static_cast<int>(p), nrm1);
        p -= static_cast<Real>(m);
        p = std::min(p, Real(1));
        cr[s] = p;
        cm[s] = m;
        const Real* c = rho_tab + 4 * m;
        const Real v = ((c[0] * p + c[1]) * p + c[2]) * p + c[3];
        rho_i += v;
        rho[k] += v;
      }
      rho[i] += rho_i;
    }
  }
}

// F(rho) and F'(rho) of one atom (F continued linearly beyond the last knot).
template <class Real>
void embed(const EamOneType<Real>& t, double rho, double& F, double& Fp) {
  double p = rho * t.rdrho + 1.0;
  int m = static_cast<int>(p);
  m = std::max(1, std::min(m, t.nrho - 1));
  p -= m;
  p = std::min(p, 1.0);
  const double* c = t.frho + 7 * m;
  Fp = (c[0] * p + c[1]) * p + c[2];
  F = ((c[3] * p + c[4]) * p + c[5]) * p + c[6];
  if (rho > t.rhomax) F += Fp * (rho - t.rhomax);
}

// The force pass of the pairs the density pass kept, atoms [0, n): each pair's force
// added to atom i's and taken from the partner's in f (x, y, z, 0 per entry of q), the
// pair energies summed into epair (Tally), half of each pair's energy and virial to both
// atoms' e_atom and w_atom (PerAtom).
template <class Real, bool PerAtom, bool Tally>
void force_pass(const EamOneType<Real>& t, const double* __restrict q, const double* __restrict fpa, int n,
                const CutPairs<Real>& cp, double* __restrict f, double& epair, double* __restrict e_atom,
                double* __restrict w_atom) {
  const Real* __restrict pair_tab = t.pair_tab;
  const int* __restrict ck = cp.ck;
  const int* __restrict cm = cp.cm;
  const Real* __restrict cr = cp.cr;
  const Real* __restrict cri = cp.cri;
  for (int i = 0; i < n; ++i) {
    const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
    const Real fpi = static_cast<Real>(fpa[i]);
    double fxi = 0, fyi = 0, fzi = 0;
    int s = cp.cbeg[i];
    const int end = cp.cend[i];
#if HWY_TARGET != HWY_SCALAR
    if constexpr (!PerAtom) {
      double fi[4] = {0.0, 0.0, 0.0, 0.0};
      s = force<Real, kG<Real>, Tally>(q, i, fpi, fpa, pair_tab, ck, cr, cri, cm, s, end, f, fi, epair);
      if constexpr (kG<Real> == 8) s = force<Real, 4, Tally>(q, i, fpi, fpa, pair_tab, ck, cr, cri, cm, s, end, f, fi, epair);
      fxi = fi[0], fyi = fi[1], fzi = fi[2];
    }
#endif
    for (; s < end; ++s) {
      const int k = ck[s];
      const Real p = cr[s];
      const Real* c = pair_tab + kEamPairStride * cm[s];
      const Real rhop = (c[0] * p + c[1]) * p + c[2];
      const Real z2p = (c[3] * p + c[4]) * p + c[5];
      const Real z2 = ((c[6] * p + c[7]) * p + c[8]) * p + c[9];
      const Real recip = cri[s];
      const Real phi = z2 * recip;
      const Real phip = z2p * recip - phi * recip;
      const Real psip = fpi * rhop + static_cast<Real>(fpa[k]) * rhop + phip;
      const double fpair = -psip * recip;
      const double dx = xi - q[4 * k], dy = yi - q[4 * k + 1], dz = zi - q[4 * k + 2];
      const double ffx = dx * fpair, ffy = dy * fpair, ffz = dz * fpair;
      fxi += ffx;
      fyi += ffy;
      fzi += ffz;
      f[4 * k] -= ffx;
      f[4 * k + 1] -= ffy;
      f[4 * k + 2] -= ffz;
      if constexpr (Tally) epair += phi;
      if constexpr (PerAtom) {
        e_atom[i] += 0.5 * phi;
        e_atom[k] += 0.5 * phi;
        const double v6[6] = {dx * ffx, dy * ffy, dz * ffz, dx * ffy, dx * ffz, dy * ffz};
        for (int c6 = 0; c6 < 6; ++c6) {
          w_atom[6 * i + c6] += 0.5 * v6[c6];
          w_atom[6 * k + c6] += 0.5 * v6[c6];
        }
      }
    }
    f[4 * i] += fxi;
    f[4 * i + 1] += fyi;
    f[4 * i + 2] += fzi;
  }
}

// The virial as the sum over entries of x f (before any forces are folded): equal to
// the pair sum of r_ab f_ab (eq. 2.25), as LAMMPS's fdotr.
inline void add_fdotr(const double* __restrict q, const double* __restrict f, int n, double* v) {
  double vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0;
  for (int k = 0; k < n; ++k) {
    const double* xk = q + 4 * k;
    const double* fk = f + 4 * k;
    vxx += xk[0] * fk[0], vyy += xk[1] * fk[1], vzz += xk[2] * fk[2];
    vxy += xk[0] * fk[1], vxz += xk[0] * fk[2], vyz += xk[1] * fk[2];
  }
  v[0] += vxx, v[1] += vyy, v[2] += vzz, v[3] += vxy, v[4] += vxz, v[5] += vyz;
}

template <class Real>
CutPairs<Real> cut_pairs(std::size_t nslot, int natom) {
  Scratch& sc = scratch;
  sc.cut_k.resize(nslot);
  sc.cut_m.resize(nslot);
  sc.cut_first.resize(natom);
  sc.cut_end.resize(natom);
  if constexpr (std::is_same_v<Real, double>) {
    sc.cut_r.resize(nslot);
    sc.cut_ri.resize(nslot);
    return {sc.cut_k.data(), sc.cut_r.data(), sc.cut_ri.data(), sc.cut_m.data(), sc.cut_first.data(), sc.cut_end.data()};
  } else {
    sc.cut_rf.resize(nslot);
    sc.cut_rif.resize(nslot);
    return {sc.cut_k.data(), sc.cut_rf.data(), sc.cut_rif.data(), sc.cut_m.data(), sc.cut_first.data(),
            sc.cut_end.data()};
  }
}

// One thread over the whole list: pair shares scattered into the entries, ghosts folded
// into their owners between the passes and at the end (forces and per-atom tallies).
template <class Real, bool PerAtom, bool Tally>
ForceSums one_type(const EamOneType<Real>& t, const Neighbors& nb, ForceWork& w) {
  const int nlocal = nb.nlocal;
  const double* q = nb.xyz.data();
  const CutPairs<Real> cp = cut_pairs<Real>(nb.list.size(), nlocal);
  density_pass(t, q, nb.first.data(), nb.list.data(), nlocal, 0, cp, w.rho.data());
  nb.fold(w.rho);

  double embed_sum = 0;
  for (int i = 0; i < nlocal; ++i) {
    double F;
    embed(t, w.rho[i], F, w.fp[i]);
    if constexpr (Tally) embed_sum += F;
    if constexpr (PerAtom) w.energy_atom[i] += F;
  }
  nb.forward(w.fp);

  Scratch& sc = scratch;
  sc.f4.assign(4 * static_cast<std::size_t>(nb.nall), 0.0);
  double* f = sc.f4.data();
  double epair = 0;
  force_pass<Real, PerAtom, Tally>(t, q, w.fp.data(), nlocal, cp, f, epair, w.energy_atom.data(),
                                   w.virial_atom.data());
  ForceSums sums;
  if constexpr (Tally) {
    double v[6] = {};
    add_fdotr(q, f, nb.nall, v);
    sums.energy = embed_sum + epair;
    sums.virial = {v[0], v[1], v[2], v[3], v[4], v[5]};
  }
  // Ghost forces into their owners, then the locals out.
  const int* owner = nb.owner.data();
  for (int k = nlocal; k < nb.nall; ++k) {
    double* fo = f + 4 * owner[k];
    fo[0] += f[4 * k], fo[1] += f[4 * k + 1], fo[2] += f[4 * k + 2];
  }
  for (int k = 0; k < nlocal; ++k) w.fx[k] = f[4 * k], w.fy[k] = f[4 * k + 1], w.fz[k] = f[4 * k + 2];
  if constexpr (PerAtom) {
    nb.fold(w.energy_atom);
    nb.fold(w.virial_atom, 6);
  }
  w.folded = true;
  return sums;
}

// The same passes on `threads` threads over the list's tiles (Neighbors::tiles,
// ForceWork::threads): each tile's pairs are summed into arrays of its own entries (its
// atoms and the entries they reach, in a core's cache), and every atom then adds its
// shares from all tiles in tile order; the sums run over tiles in order. Which thread
// takes which tile changes no number: every count gives the same bits, and every
// vector path the scalar loop's.
template <class Real, bool PerAtom, bool Tally>
ForceSums one_type_tiles(const EamOneType<Real>& t, const Neighbors& nb, ForceWork& w) {
  const int nlocal = nb.nlocal;
  const int ntile = static_cast<int>(nb.tile_atom.size()) - 1;
  const std::size_t ne = nb.tile_entry.size();
  const int* __restrict tile_atom = nb.tile_atom.data();
  const int* __restrict tile_first = nb.tile_first.data();
  const int* __restrict tile_entry = nb.tile_entry.data();
  const int* __restrict share_first = nb.share_first.data();
  const int* __restrict share = nb.share.data();
  const int* __restrict owner = nb.owner.data();
  const double* __restrict xyz = nb.xyz.data();

  // The calling thread's scratch, shared by the team through these pointers.
  const CutPairs<Real> cp = cut_pairs<Real>(nb.list.size(), nlocal);
  Scratch& sc = scratch;
  sc.tile_q.resize(4 * ne);
  sc.tile_rho.resize(ne);
  sc.tile_fp.resize(ne);
  sc.f4.resize(4 * ne);
  sc.tile_sums.assign(7 * static_cast<std::size_t>(ntile), 0.0);
  sc.embed_atom.resize(nlocal);
  if constexpr (PerAtom) {
    sc.tile_e.resize(ne);
    sc.tile_w.resize(6 * ne);
  }
  double* __restrict tq = sc.tile_q.data();
  double* __restrict trho = sc.tile_rho.data();
  double* __restrict tfp = sc.tile_fp.data();
  double* __restrict tf = sc.f4.data();
  double* __restrict tsum = sc.tile_sums.data();
  double* __restrict emb = sc.embed_atom.data();
  double* __restrict te_ = PerAtom ? sc.tile_e.data() : nullptr;
  double* __restrict tw_ = PerAtom ? sc.tile_w.data() : nullptr;
  double* __restrict fp = w.fp.data();
  const int threads = std::max(1, w.threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    // Each tile: its entries' positions, then the density of its pairs.
#pragma omp for schedule(dynamic)
    for (int p = 0; p < ntile; ++p) {
      const int a = tile_atom[p], u0 = tile_first[p], nu = tile_first[p + 1] - u0;
      double* q = tq + 4 * static_cast<std::size_t>(u0);
      for (int u = 0; u < nu; ++u) std::copy_n(xyz + 4 * static_cast<std::size_t>(tile_entry[u0 + u]), 4, q + 4 * u);
      std::fill_n(trho + u0, nu, 0.0);
      const CutPairs<Real> tp{cp.ck, cp.cr, cp.cri, cp.cm, cp.cbeg + a, cp.cend + a};
      density_pass(t, q, nb.first.data() + a, nb.tile_list.data(), tile_atom[p + 1] - a, nb.first[a], tp, trho + u0);
    }
    // Each atom: its shares of density, F and F'.
#pragma omp for schedule(dynamic, 256)
    for (int j = 0; j < nlocal; ++j) {
      double r = 0;
      for (int v = share_first[j]; v < share_first[j + 1]; ++v) r += trho[share[v]];
      w.rho[j] = r;
      double F;
      embed(t, r, F, fp[j]);
      if constexpr (Tally) emb[j] = F;
    }
    // Each tile: F' of its entries, then the forces of its pairs (and its sums).
#pragma omp for schedule(dynamic)
    for (int p = 0; p < ntile; ++p) {
      const int a = tile_atom[p], u0 = tile_first[p], nu = tile_first[p + 1] - u0;
      for (int u = 0; u < nu; ++u) tfp[u0 + u] = fp[owner[tile_entry[u0 + u]]];
      double* f = tf + 4 * static_cast<std::size_t>(u0);
      std::fill_n(f, 4 * static_cast<std::size_t>(nu), 0.0);
      if constexpr (PerAtom) {
        std::fill_n(te_ + u0, nu, 0.0);
        std::fill_n(tw_ + 6 * static_cast<std::size_t>(u0), 6 * static_cast<std::size_t>(nu), 0.0);
      }
      const CutPairs<Real> tp{cp.ck, cp.cr, cp.cri, cp.cm, cp.cbeg + a, cp.cend + a};
      const double* q = tq + 4 * static_cast<std::size_t>(u0);
      double epair = 0;
      force_pass<Real, PerAtom, Tally>(t, q, tfp + u0, tile_atom[p + 1] - a, tp, f, epair,
                                       PerAtom ? te_ + u0 : nullptr, PerAtom ? tw_ + 6 * static_cast<std::size_t>(u0) : nullptr);
      if constexpr (Tally) {
        tsum[7 * p] = epair;
        add_fdotr(q, f, nu, tsum + 7 * p + 1);
      }
    }
    // Each atom: its shares of force (and of the per-atom tallies).
#pragma omp for schedule(dynamic, 256)
    for (int j = 0; j < nlocal; ++j) gather_shares(nb, j, tf, PerAtom, PerAtom ? emb[j] : 0.0, te_, tw_, w);
  }

  ForceSums sums;
  if constexpr (Tally) sums = sum_tiles(emb, nlocal, tsum, ntile);
  w.folded = true;
  return sums;
}

template <class Real>
ForceSums one_type_any(const EamOneType<Real>& t, const Neighbors& nb, ForceWork& w) {
  // One tile is the whole list: the scattering form is the faster one there.
  if (nb.tiles && nb.tile_atom.size() > 2) {
    if (w.per_atom) return one_type_tiles<Real, true, true>(t, nb, w);
    if (w.tally) return one_type_tiles<Real, false, true>(t, nb, w);
    return one_type_tiles<Real, false, false>(t, nb, w);
  }
  if (w.per_atom) return one_type<Real, true, true>(t, nb, w);
  if (w.tally) return one_type<Real, false, true>(t, nb, w);
  return one_type<Real, false, false>(t, nb, w);
}

}  // namespace

ForceSums one_type_double(const EamOneType<double>& t, const Neighbors& nb, ForceWork& w) {
  return one_type_any(t, nb, w);
}
ForceSums one_type_float(const EamOneType<float>& t, const Neighbors& nb, ForceWork& w) {
  return one_type_any(t, nb, w);
}

// The path this copy of the kernel is, for eam_isa_dispatched.
int64_t dispatched_target() { return HWY_TARGET; }

}  // namespace mpmx::md::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::md {

HWY_EXPORT(one_type_double);
HWY_EXPORT(one_type_float);
HWY_EXPORT(dispatched_target);

ForceSums eam_one_type(const EamOneType<double>& t, const Neighbors& nb, ForceWork& w) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(one_type_double)(t, nb, w);
}

ForceSums eam_one_type(const EamOneType<float>& t, const Neighbors& nb, ForceWork& w) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(one_type_float)(t, nb, w);
}

std::string eam_isa_dispatched() {
  isa_prepare();
  return isa_name(HWY_DYNAMIC_DISPATCH(dispatched_target)());
}

std::string eam_isa_summary() {
  std::string paths, machine;
  auto add = [](std::string& list, const std::string& name) {
    if (!list.empty()) list += ' ';
    list += name;
  };
  for (int64_t mask = HWY_TARGETS; mask != 0; mask &= mask - 1) add(paths, isa_name(mask & -mask));
  for (const std::string& name : isa_supported()) add(machine, name);
  return "MD kernels: paths " + paths + "; this machine: " + machine + "; chosen: " + eam_isa_dispatched();
}

}  // namespace mpmx::md
#endif  // HWY_ONCE
