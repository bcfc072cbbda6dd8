// The few vector operations the 1-D kernels need, written once with Google Highway for
// any vector tag D (doubles) of the target being compiled. The kernels' .cpp files
// include this once per target (hwy/foreach_target.h), hence the per-target include
// guard instead of #pragma once. Where the kernels rely on one rounding, fmadd asks for
// it (a fused multiply-add where the target has one, as GCC contracts a * b + c there);
// sums across lanes go in the order the hand-written per-ISA kernels used, so the 128-bit
// path gives what the default (SSE2) build gave, and the AVX2 and AVX-512 paths what an
// AVX2 build gave, bit for bit (where cells hold four particles or more: below, the
// per-cell sums go two lanes, see per_cell_sums).

#if defined(MPMX_MPM_FUSED1D_SIMD_HPP_) == defined(HWY_TARGET_TOGGLE)
#ifdef MPMX_MPM_FUSED1D_SIMD_HPP_
#undef MPMX_MPM_FUSED1D_SIMD_HPP_
#else
#define MPMX_MPM_FUSED1D_SIMD_HPP_
#endif

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace mpmx::mpm::shape::HWY_NAMESPACE::simd {

namespace hn = hwy::HWY_NAMESPACE;

// The tags the kernels use. Per-cell sums, g2p and the locate pass go at most four
// lanes: at the usual four particles per cell a wider vector straddles two cells, so
// the sums could not take one vector a cell (on AVX-512 that made mpm 2x slower than
// AVX2; docs/performance.md, 2026-12-01). Per-point work (the DDMP weights) takes the
// target's whole width.
using D4 = hn::CappedTag<double, 4>;
using DFull = hn::ScalableTag<double>;

template <class D>
inline constexpr int kLanes = static_cast<int>(hn::MaxLanes(D()));

template <class D>
using DI = hn::Rebind<int32_t, D>;  // the cells of a vector of points

HWY_INLINE double fmadd(double a, double b, double c) {
  // One lane of the target's MulAdd: fused exactly where the vector form is.
  const hn::CappedTag<double, 1> d1;
  return hn::GetLane(hn::MulAdd(hn::Set(d1, a), hn::Set(d1, b), hn::Set(d1, c)));
}
template <class V>
HWY_INLINE V fmadd(V a, V b, V c) {
  return hn::MulAdd(a, b, c);
}

template <class D>
HWY_INLINE hn::Vec<D> load(D d, const double* p) {
  return hn::LoadU(d, p);
}
template <class V>
HWY_INLINE void store(double* p, V v) {
  hn::StoreU(v, hn::DFromV<V>(), p);
}
HWY_INLINE void store(double* p, double v) { *p = v; }

// For code written once for a vector (T = hn::Vec<D>) and for one value (T = double).
template <class T>
HWY_INLINE T load_as(const double* p) {
  if constexpr (std::is_same_v<T, double>)
    return *p;
  else
    return hn::LoadU(hn::DFromV<T>(), p);
}
template <class T>
HWY_INLINE T splat_as(double a) {
  if constexpr (std::is_same_v<T, double>)
    return a;
  else
    return hn::Set(hn::DFromV<T>(), a);
}

// The cells of kLanes points from p on, as doubles.
template <class D>
HWY_INLINE hn::Vec<D> load_cells_as_double(D d, const int* p) {
  return hn::PromoteTo(d, hn::LoadU(DI<D>(), p));
}
// Whether each of the kLanes cells from `cell` on equals c.
template <class D>
HWY_INLINE hn::Mask<DI<D>> cells_equal(D, const int* cell, int c) {
  return hn::Eq(hn::LoadU(DI<D>(), cell), hn::Set(DI<D>(), c));
}
template <class D>
HWY_INLINE bool all(D, hn::Mask<DI<D>> m) {
  return hn::AllTrue(DI<D>(), m);
}
// The first lane where m is false (m must have one).
template <class D>
HWY_INLINE int first_false(D, hn::Mask<DI<D>> m) {
  return static_cast<int>(hn::FindFirstTrue(DI<D>(), hn::Not(m)));
}
// A mask as bits, lane k at bit k (at most eight lanes).
template <class D>
HWY_INLINE unsigned bits(D d, hn::Mask<D> m) {
  static_assert(kLanes<D> <= 8);
  uint8_t b[8] = {};
  hn::StoreMaskBits(d, m, b);
  return b[0];
}

// Table lookups for a vector of points whose cells lie within kLanes of the first, c0:
// from four lanes on, one load of the kLanes entries from c0 on and a permute in registers
// (no gather); at two lanes or one, a load per lane, shorter there than the masks and
// blend of a permute.
template <class D>
struct LaneOffsets {
  int at[kLanes<D>];
};
template <class D>
using Lookup = std::conditional_t<(kLanes<D> > 2), decltype(hn::IndicesFromVec(D(), hn::Zero(hn::Rebind<int64_t, D>()))),
                                  LaneOffsets<D>>;
template <class D>
HWY_INLINE Lookup<D> lookup_index(D d, const int* cell, int c0) {
  if constexpr (kLanes<D> > 2) {
    const auto rel = hn::Sub(hn::LoadU(DI<D>(), cell), hn::Set(DI<D>(), c0));
    return hn::IndicesFromVec(d, hn::PromoteTo(hn::Rebind<int64_t, D>(), rel));
  } else {
    LaneOffsets<D> o;
    for (int k = 0; k < kLanes<D>; ++k) o.at[k] = cell[k] - c0;
    return o;
  }
}
template <class D>
HWY_INLINE hn::Vec<D> lookup(D d, const double* from_c0, Lookup<D> idx) {
  if constexpr (kLanes<D> > 2) {
    return hn::TableLookupLanes(hn::LoadU(d, from_c0), idx);
  } else {
    double v[kLanes<D>];
    for (int k = 0; k < kLanes<D>; ++k) v[k] = from_c0[idx.at[k]];
    return hn::LoadU(d, v);
  }
}

// The lanes, in order.
template <class V>
HWY_INLINE void lanes(V v, double* out) {
  hn::StoreU(v, hn::DFromV<V>(), out);
}
// Sum of the lanes, lane 0 first.
template <class V>
HWY_INLINE double sum(V v) {
  double s = 0.0;
#pragma GCC unroll 8  // constant lane numbers: extracts in registers, not through memory
  for (int k = 0; k < kLanes<hn::DFromV<V>>; ++k) s += hn::ExtractLane(v, static_cast<std::size_t>(k));
  return s;
}

// The lane sums of four vectors into out[0..3]: at four lanes by pairwise adds across the
// vectors (a transpose as it goes, as AVX's hadd did), one store for the four.
template <class V>
HWY_INLINE void sum4(const V* a, double* out) {
#if HWY_TARGET == HWY_SCALAR  // one lane: no shuffles in Highway's scalar target
  for (int j = 0; j < 4; ++j) out[j] = sum(a[j]);
#else
  using D = hn::DFromV<V>;
  constexpr int K = kLanes<D>;
  if constexpr (K == 4) {
    const D d;
    // [a0 + a1 of h0, of h1, a2 + a3 of h0, of h1], and the same for h2, h3.
    auto pairs = [&](V h0, V h1) { return hn::Add(hn::InterleaveLower(d, h0, h1), hn::InterleaveUpper(d, h0, h1)); };
    const V h01 = pairs(a[0], a[1]), h23 = pairs(a[2], a[3]);
    hn::StoreU(hn::Add(hn::ConcatLowerLower(d, h23, h01), hn::ConcatUpperUpper(d, h23, h01)), d, out);
  } else {
    for (int j = 0; j < 4; ++j) out[j] = sum(a[j]);
  }
#endif
}

// alpha of eq. 3.27 at the fraction f: with t = f (1 - f), alpha = 0.5 (4 t)^{3/2} =
// 4 t sqrt(t). t as f (1 - f): 1 - f is exact near f = 1, where f - f^2 would cancel; t
// may come a hair below zero at a cell's end: clamped. By the vector square root on every
// path, so that the wide paths agree bit for bit (on AVX-512 a series from the 14-bit
// estimate is faster but gives other last bits: docs/performance.md, 2026-12-01).
template <class V>
HWY_INLINE V alpha(V f) {
  const hn::DFromV<V> d;
  const V t = hn::Max(f * (hn::Set(d, 1.0) - f), hn::Zero(d));
  return (hn::Set(d, 4.0) * t) * hn::Sqrt(t);
}

}  // namespace mpmx::mpm::shape::HWY_NAMESPACE::simd
HWY_AFTER_NAMESPACE();

#endif  // per-target include guard
