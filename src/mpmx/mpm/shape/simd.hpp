#pragma once
// The vector width of the build and the few operations the 1-D kernels need on it,
// written once for AVX-512 (8 doubles), AVX (4) and SSE2 (2) with GCC's vector types.
// Arithmetic on `vdouble` is element-wise. GCC may fuse a * b + c on its own (as in
// scalar C++ code) or not; where the kernels rely on one rounding, fmadd asks for it.

#include <cmath>
#include <cstring>
#include <type_traits>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace mpmx::mpm::shape::simd {

#if defined(__AVX512F__)
inline constexpr int kLanes = 8;
#elif defined(__AVX__)
inline constexpr int kLanes = 4;
#else
inline constexpr int kLanes = 2;
#endif

using vdouble = double __attribute__((vector_size(8 * kLanes)));
using vint = int __attribute__((vector_size(4 * kLanes)));

[[gnu::always_inline]] inline vdouble load(const double* p) {
  vdouble v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store(double* p, vdouble v) { std::memcpy(p, &v, sizeof v); }
[[gnu::always_inline]] inline vdouble splat(double a) { return vdouble{} + a; }
// For code written once for a vector (T = vdouble) and for one value (T = double).
template <class T>
[[gnu::always_inline]] inline T load_as(const double* p) {
  if constexpr (std::is_same_v<T, double>)
    return *p;
  else
    return load(p);
}
[[gnu::always_inline]] inline void store(double* p, double v) { *p = v; }

// Truncation to int and back, one instruction each where the machine has it.
[[gnu::always_inline]] inline vint to_int(vdouble a) {
#if defined(__AVX512F__)
  return (vint)_mm512_maskz_cvttpd_epi32(0xFF, (__m512d)a);  // maskz: GCC 12 warns on the plain form
#elif defined(__AVX__)
  return (vint)_mm256_cvttpd_epi32((__m256d)a);
#else
  return __builtin_convertvector(a, vint);
#endif
}
[[gnu::always_inline]] inline vdouble to_double(vint a) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_cvtepi32_pd(0xFF, (__m256i)a);
#elif defined(__AVX__)
  return (vdouble)_mm256_cvtepi32_pd((__m128i)a);
#else
  return __builtin_convertvector(a, vdouble);
#endif
}
// Truncation towards zero, kept in double (one instruction where the machine has it).
[[gnu::always_inline]] inline vdouble trunc(vdouble a) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_roundscale_pd(0xFF, (__m512d)a, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
#elif defined(__AVX__)
  return (vdouble)_mm256_round_pd((__m256d)a, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
#else
  return to_double(to_int(a));
#endif
}
[[gnu::always_inline]] inline vdouble load_cells(const int* p) {
  vint c;
  std::memcpy(&c, p, sizeof c);
  return to_double(c);
}

// Whether the kLanes cells stored from `cell` on all equal c (as int lanes), and
// whether every lane of such a test holds.
[[gnu::always_inline]] inline vint cells_equal(const int* cell, int c) {
  vint v;
  std::memcpy(&v, cell, sizeof v);
  return v == c;
}
[[gnu::always_inline]] inline bool all(vint m) {
#if defined(__AVX512F__)
  return _mm256_movemask_ps((__m256)m) == 0xFF;
#elif defined(__AVX__)
  return _mm_movemask_ps((__m128)m) == 0xF;
#else
  for (int k = 0; k < kLanes; ++k)
    if (!m[k]) return false;
  return true;
#endif
}

// A lane mask (a comparison's result: all ones or zero per lane) as bits, lane k at bit k.
using vmask = long long __attribute__((vector_size(8 * kLanes)));
[[gnu::always_inline]] inline unsigned bits(vmask m) {
#if defined(__AVX512F__)
  return _mm512_cmpneq_epi64_mask((__m512i)m, _mm512_setzero_si512());
#elif defined(__AVX__)
  return static_cast<unsigned>(_mm256_movemask_pd((__m256d)m));
#elif defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_pd((__m128d)m));
#else
  unsigned b = 0;
  for (int k = 0; k < kLanes; ++k) b |= (m[k] != 0) << k;
  return b;
#endif
}

// Table lookups for a vector of points whose cells lie within kLanes of the first, c0:
// one load of the kLanes entries from c0 on and a permute in registers (no gather).
#if defined(__AVX512F__)
using Lookup = __m512i;
[[gnu::always_inline]] inline Lookup lookup_index(const int* cell, int c0) {
  // maskz forms: GCC 12 warns on the unmasked ones' undefined pass-through operand.
  const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cell));
  return _mm512_maskz_cvtepi32_epi64(0xFF, _mm256_sub_epi32(c, _mm256_set1_epi32(c0)));
}
[[gnu::always_inline]] inline vdouble lookup(const double* from_c0, Lookup idx) {
  return (vdouble)_mm512_maskz_permutexvar_pd(0xFF, idx, _mm512_loadu_pd(from_c0));
}
#elif defined(__AVX2__)
using Lookup = __m256i;  // as pairs of 32-bit lanes: 2 d, 2 d + 1
[[gnu::always_inline]] inline Lookup lookup_index(const int* cell, int c0) {
  const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cell));
  const __m256i d2 = _mm256_slli_epi64(_mm256_cvtepi32_epi64(_mm_sub_epi32(c, _mm_set1_epi32(c0))), 1);
  return _mm256_or_si256(d2, _mm256_slli_epi64(_mm256_add_epi64(d2, _mm256_set1_epi64x(1)), 32));
}
[[gnu::always_inline]] inline vdouble lookup(const double* from_c0, Lookup idx) {
  return (vdouble)_mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(_mm256_loadu_pd(from_c0)), idx));
}
#else
using Lookup = vint;
[[gnu::always_inline]] inline Lookup lookup_index(const int* cell, int c0) {
  vint d;
  for (int k = 0; k < kLanes; ++k) d[k] = cell[k] - c0;
  return d;
}
[[gnu::always_inline]] inline vdouble lookup(const double* from_c0, Lookup idx) {
  vdouble v;
  for (int k = 0; k < kLanes; ++k) v[k] = from_c0[idx[k]];
  return v;
}
#endif

// Sum of the lanes.
[[gnu::always_inline]] inline double sum(vdouble v) {
  double s = 0.0;
  for (int k = 0; k < kLanes; ++k) s += v[k];
  return s;
}

// The lane sums of four vectors into out[0..3]: where the machine has AVX, by pairwise
// adds across the vectors (a transpose as it goes), one store for the four.
[[gnu::always_inline]] inline void sum4(const vdouble* a, double* out) {
#if defined(__AVX512F__)
  __m256d h[4];
  for (int j = 0; j < 4; ++j) {  // the halves by copy: GCC 12 warns on the 512-bit extracts
    __m256d lo, hi;
    std::memcpy(&lo, &a[j], sizeof lo);
    std::memcpy(&hi, reinterpret_cast<const char*>(&a[j]) + sizeof lo, sizeof hi);
    h[j] = _mm256_add_pd(lo, hi);
  }
#elif defined(__AVX__)
  const __m256d h[4] = {(__m256d)a[0], (__m256d)a[1], (__m256d)a[2], (__m256d)a[3]};
#endif
#if defined(__AVX__)
  const __m256d h01 = _mm256_hadd_pd(h[0], h[1]), h23 = _mm256_hadd_pd(h[2], h[3]);
  _mm256_storeu_pd(out, _mm256_add_pd(_mm256_permute2f128_pd(h01, h23, 0x20),
                                      _mm256_permute2f128_pd(h01, h23, 0x31)));
#else
  for (int j = 0; j < 4; ++j) out[j] = sum(a[j]);
#endif
}

// The lane numbers 0, 1, ..., kLanes - 1.
[[gnu::always_inline]] inline vdouble lane_index() {
  vdouble v;
  for (int k = 0; k < kLanes; ++k) v[k] = k;
  return v;
}

// a * b + c, rounded once where the machine has FMA.
[[gnu::always_inline]] inline vdouble fmadd(vdouble a, vdouble b, vdouble c) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_fmadd_pd((__m512d)a, (__m512d)b, (__m512d)c);
#elif defined(__FMA__)
  return (vdouble)_mm256_fmadd_pd((__m256d)a, (__m256d)b, (__m256d)c);
#else
  return a * b + c;
#endif
}

[[gnu::always_inline]] inline double fmadd(double a, double b, double c) {
#if defined(__FMA__)
  return std::fma(a, b, c);
#else
  return a * b + c;
#endif
}

// max(a, b) for numbers (no NaN rules to keep).
[[gnu::always_inline]] inline vdouble max(vdouble a, vdouble b) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_max_pd(0xFF, (__m512d)a, (__m512d)b);  // maskz: GCC 12 warns on the plain form
#elif defined(__AVX__)
  return (vdouble)_mm256_max_pd((__m256d)a, (__m256d)b);
#elif defined(__SSE2__)
  return (vdouble)_mm_max_pd((__m128d)a, (__m128d)b);
#else
  return a > b ? a : b;
#endif
}

[[gnu::always_inline]] inline vdouble sqrt(vdouble a) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_sqrt_pd(0xFF, (__m512d)a);
#elif defined(__AVX__)
  return (vdouble)_mm256_sqrt_pd((__m256d)a);
#elif defined(__SSE2__)
  return (vdouble)_mm_sqrt_pd((__m128d)a);
#else
  for (int k = 0; k < kLanes; ++k) a[k] = __builtin_sqrt(a[k]);
  return a;
#endif
}

[[gnu::always_inline]] inline vdouble min(vdouble a, vdouble b) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_min_pd(0xFF, (__m512d)a, (__m512d)b);
#elif defined(__AVX__)
  return (vdouble)_mm256_min_pd((__m256d)a, (__m256d)b);
#elif defined(__SSE2__)
  return (vdouble)_mm_min_pd((__m128d)a, (__m128d)b);
#else
  return a < b ? a : b;
#endif
}

// 1/sqrt(r) to 14 bits (AVX-512) or 12 (the float estimate elsewhere), r in [1e-30, 1].
[[gnu::always_inline]] inline vdouble rsqrt_estimate(vdouble r) {
#if defined(__AVX512F__)
  return (vdouble)_mm512_maskz_rsqrt14_pd(0xFF, (__m512d)r);
#elif defined(__AVX__)
  return (vdouble)_mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps((__m256d)r)));
#elif defined(__SSE2__)
  return (vdouble)_mm_cvtps_pd(_mm_rsqrt_ps(_mm_cvtpd_ps((__m128d)r)));
#else
  vdouble y;
  for (int k = 0; k < kLanes; ++k) y[k] = 1.0 / __builtin_sqrt(r[k]);
  return y;
#endif
}

// alpha of eq. 3.27 at the fraction f: with t = f (1 - f), alpha = 0.5 (4 t)^{3/2} =
// 4 t sqrt(t). t as f (1 - f): 1 - f is exact near f = 1, where f - f^2 would cancel.
// Two ways, the faster one by machine (alpha):
//
// alpha_series: without the divider. y the estimate of 1/sqrt(t) and e = 1 - t y^2
// (|e| < 8e-4), 1/sqrt(t) = y (1 - e)^{-1/2}, whose series to e^5 leaves 4e-20: within a
// few ulp of the correctly rounded formula. t is clamped below at 1e-30 (alpha there is
// below 1e-44: zero to the precision of anything it is added to).
[[gnu::always_inline]] inline vdouble alpha_series(vdouble f) {
  const vdouble t = max(f * (1.0 - f), splat(1e-30));
  const vdouble y = rsqrt_estimate(t);
  const vdouble ty = t * y;  // ~ sqrt(t)
  const vdouble e = splat(1.0) - ty * y;
  // 4 (1 - e)^{-1/2} = 4 + 2 e + 3/2 e^2 + 5/4 e^3 + 35/32 e^4 + 63/64 e^5, by pairs
  // (Estrin): half the dependent steps of Horner's rule.
  const vdouble e2 = e * e, e4 = e2 * e2;
  const vdouble p01 = fmadd(e, splat(2.0), splat(4.0));
  const vdouble p23 = fmadd(e, splat(1.25), splat(1.5));
  const vdouble p45 = fmadd(e, splat(63.0 / 64.0), splat(35.0 / 32.0));
  return (t * ty) * fmadd(e4, p45, fmadd(e2, p23, p01));
}

// alpha_sqrt: the SIMD square root. t may come a hair below zero at a cell's end: clamped.
[[gnu::always_inline]] inline vdouble alpha_sqrt(vdouble f) {
  const vdouble t = max(f * (1.0 - f), vdouble{});
  return (4.0 * t) * sqrt(t);
}

// AVX-512 cores (Zen 4) take the series; with only the 12-bit float estimate to start
// from, the divider is faster (Zen 3: 2.3 against 3.4 cycles per value).
[[gnu::always_inline]] inline vdouble alpha(vdouble f) {
#if defined(__AVX512F__)
  return alpha_series(f);
#else
  return alpha_sqrt(f);
#endif
}

}  // namespace mpmx::mpm::shape::simd
