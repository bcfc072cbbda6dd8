#include "mpmx/md/potential/eam.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/eam_kernel.hpp"

namespace mpmx::md {

// Force-pass record per knot: rho c0..c2, z2r c0..c6 (unpadded: a smaller table beats
// line alignment, an 80-byte record touches two lines either way).
constexpr int kPairStride = 10;

#if defined(__AVX2__)
namespace {

// Lane choices for a 4-bit mask: the set lanes first, in order (as 32-bit indices, and
// as pairs of them for 64-bit lanes).
struct Compact {
  alignas(16) int i4[16][4];
  alignas(32) int i8[16][8];
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

// The filter of compute_one_type four candidates at a time: r^2 from the positions
// (x, y, z, pad per atom: one load each, transposed in registers), and the neighbours
// within the cut-off written packed by a permute (no branch). The same arithmetic as
// the scalar loop, in the same order. Returns the first candidate left for it.
template <class Real>
int filter4(const double* __restrict q, int i, const int* __restrict list, int s, int end,
            double cutsq, int* __restrict ck, Real* __restrict cr, int& npair) {
  const __m256d xi = _mm256_loadu_pd(q + 4 * i), cut = _mm256_set1_pd(cutsq);
  for (; s + 4 <= end; s += 4) {
    const __m128i k = _mm_loadu_si128(reinterpret_cast<const __m128i*>(list + s));
    const __m256d d0 = _mm256_sub_pd(xi, _mm256_loadu_pd(q + 4 * list[s]));
    const __m256d d1 = _mm256_sub_pd(xi, _mm256_loadu_pd(q + 4 * list[s + 1]));
    const __m256d d2 = _mm256_sub_pd(xi, _mm256_loadu_pd(q + 4 * list[s + 2]));
    const __m256d d3 = _mm256_sub_pd(xi, _mm256_loadu_pd(q + 4 * list[s + 3]));
    const __m256d t0 = _mm256_unpacklo_pd(d0, d1), t1 = _mm256_unpackhi_pd(d0, d1);
    const __m256d t2 = _mm256_unpacklo_pd(d2, d3), t3 = _mm256_unpackhi_pd(d2, d3);
    const __m256d dx = _mm256_permute2f128_pd(t0, t2, 0x20), dz = _mm256_permute2f128_pd(t0, t2, 0x31);
    const __m256d dy = _mm256_permute2f128_pd(t1, t3, 0x20);
#if defined(__FMA__)
    // As GCC contracts the scalar dx dx + dy dy + dz dz.
    const __m256d rsq = _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dx, dx, _mm256_mul_pd(dy, dy)));
#else
    const __m256d rsq = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                                      _mm256_mul_pd(dz, dz));
#endif
    const int m = _mm256_movemask_pd(_mm256_cmp_pd(rsq, cut, _CMP_LT_OQ));
    const __m128i pick = _mm_load_si128(reinterpret_cast<const __m128i*>(kCompact.i4[m]));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(ck + npair),
                     _mm_castps_si128(_mm_permutevar_ps(_mm_castsi128_ps(k), pick)));
    if constexpr (std::is_same_v<Real, float>) {
      _mm_storeu_ps(cr + npair, _mm_permutevar_ps(_mm256_cvtpd_ps(rsq), pick));
    } else {
      const __m256i pick8 = _mm256_load_si256(reinterpret_cast<const __m256i*>(kCompact.i8[m]));
      _mm256_storeu_pd(cr + npair, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(rsq), pick8)));
    }
    npair += __builtin_popcount(static_cast<unsigned>(m));
  }
  return s;
}


#if defined(__FMA__)
// The force pass of compute_one_type (mixed precision, no per-atom tallies) four pairs
// of atom i at a time: the four knot records transposed in registers, the spline and
// pair force in float lanes, and each pair's force (x, y, z, 0) as one double vector
// (the positions are packed so), added to i's sum and taken from k's in pair order.
// The same operations as the scalar loop, contracted as GCC contracts it there, so the
// result is the same to the bit. Returns the first pair left for the scalar loop.
template <bool Tally>
int force4(const double* __restrict q, int i, float fpi, const double* __restrict fpa,
           const float* __restrict pair_tab, const int* __restrict ck, const float* __restrict cr,
           const float* __restrict cri, const int* __restrict cm, int s, int end,
           double* __restrict f, __m256d& fi, double& epair) {
  const __m256d xi = _mm256_loadu_pd(q + 4 * i);
  const __m128 vfpi = _mm_set1_ps(fpi);
  for (; s + 4 <= end; s += 4) {
    const int k0 = ck[s], k1 = ck[s + 1], k2 = ck[s + 2], k3 = ck[s + 3];
    const float* c0 = pair_tab + kPairStride * cm[s];
    const float* c1 = pair_tab + kPairStride * cm[s + 1];
    const float* c2 = pair_tab + kPairStride * cm[s + 2];
    const float* c3 = pair_tab + kPairStride * cm[s + 3];
    __m128 A0 = _mm_loadu_ps(c0), A1 = _mm_loadu_ps(c1), A2 = _mm_loadu_ps(c2), A3 = _mm_loadu_ps(c3);
    _MM_TRANSPOSE4_PS(A0, A1, A2, A3);  // coefficients 0..3 of the four pairs
    __m128 B0 = _mm_loadu_ps(c0 + 4), B1 = _mm_loadu_ps(c1 + 4), B2 = _mm_loadu_ps(c2 + 4),
           B3 = _mm_loadu_ps(c3 + 4);
    _MM_TRANSPOSE4_PS(B0, B1, B2, B3);  // 4..7
    auto tail = [](const float* c) {     // 8, 9
      return _mm_castpd_ps(_mm_load_sd(reinterpret_cast<const double*>(c + 8)));
    };
    const __m128 h01 = _mm_unpacklo_ps(tail(c0), tail(c1)), h23 = _mm_unpacklo_ps(tail(c2), tail(c3));
    const __m128 C8 = _mm_movelh_ps(h01, h23), C9 = _mm_movehl_ps(h23, h01);
    const __m128 p = _mm_loadu_ps(cr + s), recip = _mm_loadu_ps(cri + s);
    const __m128 rhop = _mm_fmadd_ps(_mm_fmadd_ps(A0, p, A1), p, A2);
    const __m128 z2p = _mm_fmadd_ps(_mm_fmadd_ps(A3, p, B0), p, B1);
    const __m128 z2 = _mm_fmadd_ps(_mm_fmadd_ps(_mm_fmadd_ps(B2, p, B3), p, C8), p, C9);
    const __m128 phi = _mm_mul_ps(z2, recip);
    const __m128 phip = _mm_fmsub_ps(z2p, recip, _mm_mul_ps(phi, recip));
    const __m128 fpk = _mm256_cvtpd_ps(_mm256_set_pd(fpa[k3], fpa[k2], fpa[k1], fpa[k0]));
    const __m128 psip = _mm_add_ps(_mm_fmadd_ps(vfpi, rhop, _mm_mul_ps(fpk, rhop)), phip);
    const __m256d fpair = _mm256_cvtps_pd(_mm_mul_ps(_mm_xor_ps(psip, _mm_set1_ps(-0.0f)), recip));
    auto pair = [&](int k, __m256d fp) {
      const __m256d ff = _mm256_mul_pd(_mm256_sub_pd(xi, _mm256_loadu_pd(q + 4 * k)), fp);
      fi = _mm256_add_pd(fi, ff);
      _mm256_storeu_pd(f + 4 * k, _mm256_sub_pd(_mm256_loadu_pd(f + 4 * k), ff));
    };
    pair(k0, _mm256_permute4x64_pd(fpair, 0x00));
    pair(k1, _mm256_permute4x64_pd(fpair, 0x55));
    pair(k2, _mm256_permute4x64_pd(fpair, 0xAA));
    pair(k3, _mm256_permute4x64_pd(fpair, 0xFF));
    if constexpr (Tally) {
      alignas(16) float e[4];
      _mm_store_ps(e, phi);
      for (int l = 0; l < 4; ++l) epair += e[l];
    }
  }
  return s;
}

// The density pass of compute_one_type (mixed precision) four pairs of atom i at a time:
// knot and offset in float lanes (kept for the force pass), the four knot records
// transposed in registers, the spline in lanes, then the sums in pair order. The same
// operations as the scalar loop, contracted as GCC contracts it there. Returns the first
// pair left for the scalar loop.
int density4(const float* __restrict rho_tab, float rdr, int nrm1, const int* __restrict ck,
             float* __restrict cr, int* __restrict cm, int s, int end, double* __restrict rho,
             double& rho_i) {
  const __m128 vrdr = _mm_set1_ps(rdr), one = _mm_set1_ps(1.0f);
  const __m128i last = _mm_set1_epi32(nrm1);
  for (; s + 4 <= end; s += 4) {
    __m128 p = _mm_fmadd_ps(_mm_loadu_ps(cr + s), vrdr, one);
    const __m128i m = _mm_min_epi32(_mm_cvttps_epi32(p), last);
    p = _mm_min_ps(one, _mm_sub_ps(p, _mm_cvtepi32_ps(m)));
    _mm_storeu_ps(cr + s, p);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(cm + s), m);
    alignas(16) int mi[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(mi), m);
    __m128 C0 = _mm_loadu_ps(rho_tab + 4 * mi[0]), C1 = _mm_loadu_ps(rho_tab + 4 * mi[1]),
           C2 = _mm_loadu_ps(rho_tab + 4 * mi[2]), C3 = _mm_loadu_ps(rho_tab + 4 * mi[3]);
    _MM_TRANSPOSE4_PS(C0, C1, C2, C3);
    const __m128 v = _mm_fmadd_ps(_mm_fmadd_ps(_mm_fmadd_ps(C0, p, C1), p, C2), p, C3);
    alignas(32) double vd[4];
    _mm256_store_pd(vd, _mm256_cvtps_pd(v));
    for (int l = 0; l < 4; ++l) {
      rho_i += vd[l];
      rho[ck[s + l]] += vd[l];
    }
  }
  return s;
}
#endif

}  // namespace
#endif

void eam_spline(int n, double delta, const std::vector<double>& f, double* out) {
  auto s = [out](int m, int c) -> double& { return out[7 * m + c]; };
  for (int m = 1; m <= n; ++m) s(m, 6) = f[m];
  s(1, 5) = s(2, 6) - s(1, 6);
  s(2, 5) = 0.5 * (s(3, 6) - s(1, 6));
  s(n - 1, 5) = 0.5 * (s(n, 6) - s(n - 2, 6));
  s(n, 5) = s(n, 6) - s(n - 1, 6);
  for (int m = 3; m <= n - 2; ++m)
    s(m, 5) = ((s(m - 2, 6) - s(m + 2, 6)) + 8.0 * (s(m + 1, 6) - s(m - 1, 6))) / 12.0;
  for (int m = 1; m <= n - 1; ++m) {
    s(m, 4) = 3.0 * (s(m + 1, 6) - s(m, 6)) - 2.0 * s(m, 5) - s(m + 1, 5);
    s(m, 3) = s(m, 5) + s(m + 1, 5) - 2.0 * (s(m + 1, 6) - s(m, 6));
  }
  s(n, 4) = 0.0;
  s(n, 3) = 0.0;
  for (int m = 1; m <= n; ++m) {
    s(m, 2) = s(m, 5) / delta;
    s(m, 1) = 2.0 * s(m, 4) / delta;
    s(m, 0) = 3.0 * s(m, 3) / delta;
  }
}

Eam::Eam(const EamTables& t, const std::vector<std::string>& type_elements) : file_(t.file) {
  const int ne = static_cast<int>(t.elements.size());
  if (type_elements.empty()) {
    for (int e = 0; e < ne; ++e) map_.push_back(e);
  } else {
    for (const auto& name : type_elements) {
      int e = t.element_index(name);
      if (t.format == "funcfl") e = 0;
      if (e < 0)
        throw InputError(fmt::format("{}: element '{}' is not in the file (it has: {})", t.file,
                                     name, fmt::join(t.elements, ", ")));
      map_.push_back(e);
    }
  }
  ntypes_ = static_cast<int>(map_.size());
  for (int e : map_) {
    masses_.push_back(t.masses[e]);
    names_.push_back(t.format == "funcfl" && !type_elements.empty() ? type_elements[names_.size()]
                                                                    : t.elements[e]);
  }
  nrho_ = t.nrho;
  nr_ = t.nr;
  rdr_ = 1.0 / t.dr;
  rdrho_ = 1.0 / t.drho;
  rhomax_ = t.rhomax;
  cut_ = t.cut;

  const std::size_t fr = 7 * static_cast<std::size_t>(nrho_ + 1);
  const std::size_t rr = 7 * static_cast<std::size_t>(nr_ + 1);
  frho_.assign(fr * t.frho.size(), 0.0);
  for (std::size_t f = 0; f < t.frho.size(); ++f) eam_spline(nrho_, t.drho, t.frho[f], &frho_[f * fr]);
  rhor_.assign(rr * t.rhor.size(), 0.0);
  for (std::size_t f = 0; f < t.rhor.size(); ++f) eam_spline(nr_, t.dr, t.rhor[f], &rhor_[f * rr]);
  z2r_.assign(rr * t.z2r.size(), 0.0);
  for (std::size_t f = 0; f < t.z2r.size(); ++f) eam_spline(nr_, t.dr, t.z2r[f], &z2r_[f * rr]);
  rhor_f_.assign(rhor_.begin(), rhor_.end());
  z2r_f_.assign(z2r_.begin(), z2r_.end());

  if (ntypes_ == 1) {
    const int e = map_[0];
    const double* rh = &rhor_[t.rhor_index[e * ne + e] * rr];
    const double* z2 = &z2r_[t.z2r_index[e * ne + e] * rr];
    rho1_.assign(4 * static_cast<std::size_t>(nr_ + 1), 0.0);
    pair1_.assign(kPairStride * static_cast<std::size_t>(nr_ + 1), 0.0);
    for (int m = 0; m <= nr_; ++m) {
      for (int c = 0; c < 4; ++c) rho1_[4 * m + c] = rh[7 * m + 3 + c];
      for (int c = 0; c < 3; ++c) pair1_[kPairStride * m + c] = rh[7 * m + c];
      for (int c = 0; c < 7; ++c) pair1_[kPairStride * m + 3 + c] = z2[7 * m + c];
    }
    rho1f_.assign(rho1_.begin(), rho1_.end());
    pair1f_.assign(pair1_.begin(), pair1_.end());
  }
  rho_off_.resize(ntypes_ * ntypes_);
  z2r_off_.resize(ntypes_ * ntypes_);
  frho_off_.resize(ntypes_);
  for (int a = 0; a < ntypes_; ++a) {
    frho_off_[a] = static_cast<int>(map_[a] * fr);
    for (int b = 0; b < ntypes_; ++b) {
      // density at an atom of type a due to type b: LAMMPS type2rhor[b][a]
      rho_off_[a * ntypes_ + b] = static_cast<int>(t.rhor_index[map_[b] * ne + map_[a]] * rr);
      z2r_off_[a * ntypes_ + b] = static_cast<int>(t.z2r_index[map_[a] * ne + map_[b]] * rr);
    }
  }
}

template <class Real>
struct Eam::Tables {
  const Real* rhor;
  const Real* z2r;
  const double* frho;
  const int* rho_off;
  const int* z2r_off;
  const int* frho_off;
  int ntypes, nr, nrho;
  Real rdr;
  double rdrho, rhomax, cut;

  double cutsq() const { return cut * cut; }

  // p and knot m as pair_eam computes them.
  void locate(Real r, Real& p, int& m) const {
    p = r * rdr + Real(1);
    m = static_cast<int>(p);
    m = std::min(m, nr - 1);
    p -= static_cast<Real>(m);
    p = std::min(p, Real(1));
  }
  static Real value(const Real* c, Real p) { return ((c[3] * p + c[4]) * p + c[5]) * p + c[6]; }
  static Real slope(const Real* c, Real p) { return (c[0] * p + c[1]) * p + c[2]; }

  void density(Real r, int ti, int tj, Real& at_i, Real& at_j) const {
    Real p;
    int m;
    locate(r, p, m);
    at_i = value(rhor + rho_off[ti * ntypes + tj] + 7 * m, p);
    at_j = value(rhor + rho_off[tj * ntypes + ti] + 7 * m, p);
  }
  void embed(double rho, int t, double& F, double& Fp) const {
    double p = rho * rdrho + 1.0;
    int m = static_cast<int>(p);
    m = std::max(1, std::min(m, nrho - 1));
    p -= m;
    p = std::min(p, 1.0);
    const double* c = frho + frho_off[t] + 7 * m;
    Fp = (c[0] * p + c[1]) * p + c[2];
    F = ((c[3] * p + c[4]) * p + c[5]) * p + c[6];
    if (rho > rhomax) F += Fp * (rho - rhomax);
  }
  // phi and dE/dr of the pair, with the embedding terms F_i' rho_j' + F_j' rho_i'.
  void pair(Real r, int ti, int tj, Real fpi, Real fpj, Real& phi, Real& dedr) const {
    Real p;
    int m;
    locate(r, p, m);
    const Real rhoip = slope(rhor + rho_off[tj * ntypes + ti] + 7 * m, p);  // i's density at j
    const Real rhojp = slope(rhor + rho_off[ti * ntypes + tj] + 7 * m, p);  // j's density at i
    const Real* c = z2r + z2r_off[ti * ntypes + tj] + 7 * m;
    const Real z2p = slope(c, p);
    const Real z2 = value(c, p);
    const Real recip = Real(1) / r;
    phi = z2 * recip;
    const Real phip = z2p * recip - phi * recip;
    dedr = fpi * rhojp + fpj * rhoip + phip;
  }
};

namespace {
// Per-thread scratch of the one-type kernel (not part of a System's state, so thousands
// of Systems do not each carry it): the pairs inside the cutoff found by the density
// pass (entry, r, 1/r), reused by the force pass, and packed forces.
struct Scratch {
  std::vector<int> cut_first, cut_k, cut_m;
  std::vector<double> cut_r, cut_ri;
  std::vector<float> cut_rf, cut_rif;
  std::vector<double> f4;
};
thread_local Scratch scratch;
}  // namespace

// One type: the density pass keeps the pairs inside the cutoff (entry, r), the force
// pass walks only those. Same arithmetic as pair_eam for Real = double.
template <class Real, bool PerAtom, bool Tally>
ForceSums Eam::compute_one_type(const Neighbors& nb, ForceWork& w, const Real* rho_tab,
                                const Real* pair_tab) const {
  const int nlocal = nb.nlocal;
  const double* __restrict q = nb.xyz.data();
  const int* __restrict first = nb.first.data();
  const int* __restrict list = nb.list.data();
  double* __restrict rho = w.rho.data();
  const double cutsq = cut_ * cut_;
  const Real rdr = static_cast<Real>(rdr_);
  const int nrm1 = nr_ - 1;

  Scratch& sc = scratch;
  sc.cut_first.resize(nlocal + 1);
  sc.cut_k.resize(nb.list.size());
  std::vector<Real>& rbuf = [&]() -> std::vector<Real>& {
    if constexpr (std::is_same_v<Real, double>) return sc.cut_r;
    else return sc.cut_rf;
  }();
  rbuf.resize(nb.list.size());
  std::vector<Real>& ribuf = [&]() -> std::vector<Real>& {
    if constexpr (std::is_same_v<Real, double>) return sc.cut_ri;
    else return sc.cut_rif;
  }();
  ribuf.resize(nb.list.size());
  int* __restrict ck = sc.cut_k.data();
  int* __restrict cfirst = sc.cut_first.data();
  sc.cut_m.resize(nb.list.size());
  int* __restrict cm = sc.cut_m.data();
  Real* __restrict cr = rbuf.data();
  Real* __restrict cri = ribuf.data();

  auto locate = [&](Real r, Real& p, int& m) {
    p = r * rdr + Real(1);
    m = static_cast<int>(p);
    m = std::min(m, nrm1);
    p -= static_cast<Real>(m);
    p = std::min(p, Real(1));
  };

  // In blocks of atoms (so the pair data just written is still in cache): filter the
  // candidates (branch-free: the in/out decision is unpredictable), r and 1/r in one
  // contiguous sweep (packed sqrt and division are correctly rounded: bit-identical to
  // the scalar operations), then the density; knot and offset are kept for the force pass.
  constexpr int kBlock = 64;
  int npair = 0;
  for (int i0 = 0; i0 < nlocal; i0 += kBlock) {
    const int i1 = std::min(nlocal, i0 + kBlock);
    const int start = npair;
    for (int i = i0; i < i1; ++i) {
      cfirst[i] = npair;
      const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
      int s = first[i];
#if defined(__AVX2__)
      s = filter4(q, i, list, s, first[i + 1], cutsq, ck, cr, npair);
#endif
      for (; s < first[i + 1]; ++s) {
        const int k = list[s];
        const double dx = xi - q[4 * k], dy = yi - q[4 * k + 1], dz = zi - q[4 * k + 2];
        const double rsq = dx * dx + dy * dy + dz * dz;
        ck[npair] = k;
        cr[npair] = static_cast<Real>(rsq);
        npair += rsq < cutsq;
      }
    }
    cfirst[i1] = npair;
    int s0 = start;
#if defined(__SSE2__)
    if constexpr (std::is_same_v<Real, double>) {
      const __m128d one = _mm_set1_pd(1.0);
      for (; s0 + 2 <= npair; s0 += 2) {
        const __m128d r = _mm_sqrt_pd(_mm_loadu_pd(cr + s0));
        _mm_storeu_pd(cr + s0, r);
        _mm_storeu_pd(cri + s0, _mm_div_pd(one, r));
      }
    } else {
      const __m128 one = _mm_set1_ps(1.0f);
      for (; s0 + 4 <= npair; s0 += 4) {
        const __m128 r = _mm_sqrt_ps(_mm_loadu_ps(cr + s0));
        _mm_storeu_ps(cr + s0, r);
        _mm_storeu_ps(cri + s0, _mm_div_ps(one, r));
      }
    }
#endif
    for (int s = s0; s < npair; ++s) {
      const Real r = std::sqrt(cr[s]);
      cr[s] = r;
      cri[s] = Real(1) / r;
    }
    for (int i = i0; i < i1; ++i) {
      double rho_i = 0;
      int s = cfirst[i];
#if defined(__AVX2__) && defined(__FMA__)
      if constexpr (std::is_same_v<Real, float>)
        s = density4(rho_tab, rdr, nrm1, ck, cr, cm, s, cfirst[i + 1], rho, rho_i);
#endif
      for (; s < cfirst[i + 1]; ++s) {
        const int k = ck[s];
        Real p;
        int m;
        locate(cr[s], p, m);
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
  nb.fold(w.rho);

  const double* frho = frho_.data() + frho_off_[0];
  double embed = 0;
  for (int i = 0; i < nlocal; ++i) {
    double p = rho[i] * rdrho_ + 1.0;
    int m = static_cast<int>(p);
    m = std::max(1, std::min(m, nrho_ - 1));
    p -= m;
    p = std::min(p, 1.0);
    const double* c = frho + 7 * m;
    const double fp = (c[0] * p + c[1]) * p + c[2];
    double F = ((c[3] * p + c[4]) * p + c[5]) * p + c[6];
    if (rho[i] > rhomax_) F += fp * (rho[i] - rhomax_);
    w.fp[i] = fp;
    if constexpr (Tally) embed += F;
    if constexpr (PerAtom) w.energy_atom[i] += F;
  }
  nb.forward(w.fp);

  const double* __restrict fpa = w.fp.data();
  sc.f4.assign(4 * static_cast<std::size_t>(nb.nall), 0.0);
  double* __restrict f = sc.f4.data();
  double epair = 0, vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0;
  for (int i = 0; i < nlocal; ++i) {
    const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
    const Real fpi = static_cast<Real>(fpa[i]);
    double fxi = 0, fyi = 0, fzi = 0;
    int s = cfirst[i];
#if defined(__AVX2__) && defined(__FMA__)
    if constexpr (std::is_same_v<Real, float> && !PerAtom) {
      __m256d fi = _mm256_setzero_pd();
      s = force4<Tally>(q, i, fpi, fpa, pair_tab, ck, cr, cri, cm, s, cfirst[i + 1], f, fi, epair);
      alignas(32) double a[4];
      _mm256_store_pd(a, fi);
      fxi = a[0], fyi = a[1], fzi = a[2];
    }
#endif
    for (; s < cfirst[i + 1]; ++s) {
      const int k = ck[s];
      const Real p = cr[s];
      const Real* c = pair_tab + kPairStride * cm[s];
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
        w.energy_atom[i] += 0.5 * phi;
        w.energy_atom[k] += 0.5 * phi;
        const double v6[6] = {dx * ffx, dy * ffy, dz * ffz, dx * ffy, dx * ffz, dy * ffz};
        for (int q = 0; q < 6; ++q) {
          w.virial_atom[6 * i + q] += 0.5 * v6[q];
          w.virial_atom[6 * k + q] += 0.5 * v6[q];
        }
      }
    }
    f[4 * i] += fxi;
    f[4 * i + 1] += fyi;
    f[4 * i + 2] += fzi;
  }
  ForceSums sums;
  if constexpr (Tally) {
    // Virial as sum over locals and ghosts of x f (before ghost forces are folded):
    // equal to the pair sum of r_ab f_ab (eq. 2.25), as LAMMPS's fdotr.
    for (int k = 0; k < nb.nall; ++k) {
      const double* xk = q + 4 * k;
      const double* fk = f + 4 * k;
      vxx += xk[0] * fk[0], vyy += xk[1] * fk[1], vzz += xk[2] * fk[2];
      vxy += xk[0] * fk[1], vxz += xk[0] * fk[2], vyz += xk[1] * fk[2];
    }
    sums.energy = embed + epair;
    sums.virial = {vxx, vyy, vzz, vxy, vxz, vyz};
  }
  // Ghost forces into their owners, then the locals out.
  const int* owner = nb.owner.data();
  for (int k = nlocal; k < nb.nall; ++k) {
    double* fo = f + 4 * owner[k];
    fo[0] += f[4 * k], fo[1] += f[4 * k + 1], fo[2] += f[4 * k + 2];
  }
  double* __restrict fx = w.fx.data();
  double* __restrict fy = w.fy.data();
  double* __restrict fz = w.fz.data();
  for (int k = 0; k < nlocal; ++k) fx[k] = f[4 * k], fy[k] = f[4 * k + 1], fz[k] = f[4 * k + 2];
  w.folded = true;
  return sums;
}

template <class Real>
ForceSums Eam::dispatch_one_type(const Neighbors& nb, ForceWork& w, const Real* rho_tab, const Real* pair_tab) const {
  if (w.per_atom) return compute_one_type<Real, true, true>(nb, w, rho_tab, pair_tab);
  if (w.tally) return compute_one_type<Real, false, true>(nb, w, rho_tab, pair_tab);
  return compute_one_type<Real, false, false>(nb, w, rho_tab, pair_tab);
}

ForceSums Eam::compute(const Neighbors& nb, ForceWork& w) const {
  if (ntypes_ == 1) {
    return dispatch_one_type<double>(nb, w, rho1_.data(), pair1_.data());
  }
  const Tables<double> t{rhor_.data(), z2r_.data(), frho_.data(), rho_off_.data(), z2r_off_.data(),
                         frho_off_.data(), ntypes_, nr_, nrho_, rdr_, rdrho_, rhomax_, cut_};
  return eam_compute<double>(t, nb, w);
}

ForceSums Eam::compute_mixed(const Neighbors& nb, ForceWork& w) const {
  if (ntypes_ == 1) {
    return dispatch_one_type<float>(nb, w, rho1f_.data(), pair1f_.data());
  }
  const Tables<float> t{rhor_f_.data(), z2r_f_.data(), frho_.data(), rho_off_.data(),
                        z2r_off_.data(), frho_off_.data(), ntypes_, nr_, nrho_,
                        static_cast<float>(rdr_), rdrho_, rhomax_, cut_};
  return eam_compute<float>(t, nb, w);
}

double Eam::pair_energy(double r, int ti, int tj) const {
  const Tables<double> t{rhor_.data(), z2r_.data(), frho_.data(), rho_off_.data(), z2r_off_.data(),
                         frho_off_.data(), ntypes_, nr_, nrho_, rdr_, rdrho_, rhomax_, cut_};
  double phi, dedr;
  t.pair(r, ti, tj, 0.0, 0.0, phi, dedr);
  return phi;
}

}  // namespace mpmx::md
