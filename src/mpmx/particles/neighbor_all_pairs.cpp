// The all-pairs search of a small periodic box (neighbor_all_pairs.hpp). The filter is
// compiled once per vector path of core/simd_targets.hpp (hwy/foreach_target.h includes
// this file again for each); the exact stage once, with -ffp-contract=off
// (CMakeLists.txt), as add_ghosts and the binned search: an image's position and r^2 are
// theirs, bit for bit, on every path.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the paths to compile
// clang-format on

#include "mpmx/particles/neighbor_all_pairs.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "mpmx/core/isa.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "mpmx/particles/neighbor_all_pairs.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace mpmx::particles::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

// Atom i's position and the window's constants, in every lane.
template <class D>
struct Window {
  using V = decltype(hn::Zero(D()));
  V xi, yi, zi, lx, ly, lz, xy, xz, yz, ix, iy, iz, ox, oy, oz, sx, sy, sz, wx, wy, cut;
  Window(D d, const float* x, const float* y, const float* z, int i, const ImageWindow& w)
      : xi(hn::Set(d, x[i])), yi(hn::Set(d, y[i])), zi(hn::Set(d, z[i])), lx(hn::Set(d, w.lx)), ly(hn::Set(d, w.ly)),
        lz(hn::Set(d, w.lz)), xy(hn::Set(d, w.xy)), xz(hn::Set(d, w.xz)), yz(hn::Set(d, w.yz)),
        ix(hn::Set(d, w.inv[0])), iy(hn::Set(d, w.inv[1])), iz(hn::Set(d, w.inv[2])), ox(hn::Set(d, w.lower[0])),
        oy(hn::Set(d, w.lower[1])), oz(hn::Set(d, w.lower[2])), sx(hn::Set(d, w.span[0])), sy(hn::Set(d, w.span[1])),
        sz(hn::Set(d, w.span[2])), wx(hn::Set(d, 2 * w.span[0] + 1)), wy(hn::Set(d, 2 * w.span[1] + 1)),
        cut(hn::Set(d, w.rs2)) {}
};

// The kept lanes of `near`, ascending, with `place`'s lanes, from the mask's bits
// (Highway's compress-store copies a kilobyte table onto the stack at every call in GCC
// builds: slower).
template <class D, class M, class V>
HWY_INLINE int keep(D d, M near, int j, V place, int* out, int* shift, int m) {
  uint8_t lanes[8] = {};
  hn::StoreMaskBits(d, near, lanes);
  uint64_t bits = 0;
  std::memcpy(&bits, lanes, sizeof bits);
  float places[16];
  hn::StoreU(place, d, places);
  for (; bits != 0; bits &= bits - 1) {
    const int lane = std::countr_zero(bits);
    out[m] = j + lane;
    shift[m] = static_cast<int>(places[lane]);
    ++m;
  }
  return m;
}

// One shift per axis: a box wider than twice the radius along each.
int near_one_image(const float* x, const float* y, const float* z, int i, int n, const ImageWindow& w, int* out,
                   int* shift) {
  const hn::CappedTag<float, 16> d;
  const int N = static_cast<int>(hn::Lanes(d));
  const Window<decltype(d)> k(d, x, y, z, i, w);
  int m = 0;
  for (int j = i + 1; j < n; j += N) {
    // The one shift each window allows (images as add_ghosts' loops go: z, then y under
    // z's shift, then x under both).
    const auto rz = hn::Sub(k.zi, hn::LoadU(d, z + j));
    const auto c = hn::Ceil(hn::MulSub(rz, k.iz, k.oz));
    const auto dz = hn::NegMulAdd(c, k.lz, rz);
    const auto ry = hn::NegMulAdd(c, k.yz, hn::Sub(k.yi, hn::LoadU(d, y + j)));
    const auto b = hn::Ceil(hn::MulSub(ry, k.iy, k.oy));
    const auto dy = hn::NegMulAdd(b, k.ly, ry);
    const auto rx = hn::NegMulAdd(b, k.xy, hn::NegMulAdd(c, k.xz, hn::Sub(k.xi, hn::LoadU(d, x + j))));
    const auto a = hn::Ceil(hn::MulSub(rx, k.ix, k.ox));
    const auto dx = hn::NegMulAdd(a, k.lx, rx);
    const auto near = hn::And(hn::Lt(hn::MulAdd(dx, dx, hn::MulAdd(dy, dy, hn::Mul(dz, dz))), k.cut),
                              hn::FirstN(d, static_cast<std::size_t>(n - j)));
    if (hn::AllFalse(d, near)) continue;
    // The image's place in the table's row, ((c + span) (2 span + 1) + b + span) (2 span
    // + 1) + a + span (small integers, exact).
    const auto cc = hn::Add(hn::Min(hn::Max(c, hn::Neg(k.sz)), k.sz), k.sz);
    const auto bb = hn::Add(hn::Min(hn::Max(b, hn::Neg(k.sy)), k.sy), k.sy);
    const auto aa = hn::Add(hn::Min(hn::Max(a, hn::Neg(k.sx)), k.sx), k.sx);
    const auto place = hn::MulAdd(hn::MulAdd(cc, k.wy, bb), k.wx, aa);
    m = keep(d, near, j, place, out, shift, m);
  }
  return m;
}

// Every shift of the windows (a box thin along some axis): each image kept with its
// place, those of one atom in the order of their places (add_ghosts' order). Shifts
// beyond the table's span are masked off, not clamped: two shifts clamped to one place
// would list one pair twice.
// KX, KY, KZ: the shifts per axis, fixed at compile time for the common thin boxes (two
// along an axis or two), so that the loops unroll; 0 where taken from the window.
template <int KX, int KY, int KZ>
int near_images(const float* x, const float* y, const float* z, int i, int n, const ImageWindow& w, int* out,
                int* shift) {
  const int kx = KX ? KX : w.count[0], ky = KY ? KY : w.count[1], kz = KZ ? KZ : w.count[2];
  const hn::CappedTag<float, 16> d;
  const int N = static_cast<int>(hn::Lanes(d));
  const Window<decltype(d)> k(d, x, y, z, i, w);
  const auto one = hn::Set(d, 1.0f);
  const int shifts = kx * ky * kz;
  uint64_t kept[kAllPairsMostShifts];
  float places[kAllPairsMostShifts][16];
  int m = 0;
  for (int j = i + 1; j < n; j += N) {
    const auto rz = hn::Sub(k.zi, hn::LoadU(d, z + j));
    const auto ry = hn::Sub(k.yi, hn::LoadU(d, y + j));
    const auto rx = hn::Sub(k.xi, hn::LoadU(d, x + j));
    const auto valid = hn::FirstN(d, static_cast<std::size_t>(n - j));
    uint64_t any = 0;
    int s = 0;
    // The lowest shift each window allows, then the next ones.
    auto c = hn::Ceil(hn::MulSub(rz, k.iz, k.oz));
    for (int kc = 0; kc < kz; ++kc, c = hn::Add(c, one)) {
      const auto dz = hn::NegMulAdd(c, k.lz, rz);
      const auto dz2 = hn::Mul(dz, dz);
      const auto ryc = hn::NegMulAdd(c, k.yz, ry);
      const auto rxc = hn::NegMulAdd(c, k.xz, rx);
      const auto in_c = hn::And(valid, hn::Le(hn::Abs(c), k.sz));
      auto b = hn::Ceil(hn::MulSub(ryc, k.iy, k.oy));
      for (int kb = 0; kb < ky; ++kb, b = hn::Add(b, one)) {
        const auto dy = hn::NegMulAdd(b, k.ly, ryc);
        const auto dyz2 = hn::MulAdd(dy, dy, dz2);
        const auto rxb = hn::NegMulAdd(b, k.xy, rxc);
        const auto in_cb = hn::And(in_c, hn::Le(hn::Abs(b), k.sy));
        auto a = hn::Ceil(hn::MulSub(rxb, k.ix, k.ox));
        for (int ka = 0; ka < kx; ++ka, a = hn::Add(a, one), ++s) {
          const auto dx = hn::NegMulAdd(a, k.lx, rxb);
          const auto near =
              hn::And(hn::And(in_cb, hn::Le(hn::Abs(a), k.sx)), hn::Lt(hn::MulAdd(dx, dx, dyz2), k.cut));
          uint8_t lanes[8] = {};
          hn::StoreMaskBits(d, near, lanes);
          std::memcpy(&kept[s], lanes, sizeof kept[s]);
          if (kept[s] == 0) continue;
          any |= kept[s];
          const auto place = hn::MulAdd(hn::MulAdd(hn::Add(c, k.sz), k.wy, hn::Add(b, k.sy)), k.wx, hn::Add(a, k.sx));
          hn::StoreU(place, d, places[s]);
        }
      }
    }
    for (; any != 0; any &= any - 1) {
      const int lane = std::countr_zero(any);
      for (int t = 0; t < shifts; ++t)
        if ((kept[t] >> lane) & 1) out[m] = j + lane, shift[m] = static_cast<int>(places[t][lane]), ++m;
    }
  }
  return m;
}

int near_path(const float* x, const float* y, const float* z, int i, int n, const ImageWindow& w, int* out,
              int* shift) {
  const int kx = w.count[0], ky = w.count[1], kz = w.count[2];
  if (kx == 1 && ky == 1 && kz == 1) return near_one_image(x, y, z, i, n, w, out, shift);
  if (kx <= 2 && ky <= 2 && kz <= 2) {
    using Path = int (*)(const float*, const float*, const float*, int, int, const ImageWindow&, int*, int*);
    static constexpr Path paths[8] = {nullptr,
                                      near_images<2, 1, 1>,
                                      near_images<1, 2, 1>,
                                      near_images<2, 2, 1>,
                                      near_images<1, 1, 2>,
                                      near_images<2, 1, 2>,
                                      near_images<1, 2, 2>,
                                      near_images<2, 2, 2>};
    return paths[(kx - 1) + 2 * (ky - 1) + 4 * (kz - 1)](x, y, z, i, n, w, out, shift);
  }
  return near_images<0, 0, 0>(x, y, z, i, n, w, out, shift);
}

}  // namespace mpmx::particles::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::particles {

HWY_EXPORT(near_path);

int near_later_atoms(const float* x, const float* y, const float* z, int i, int n, const ImageWindow& w, int* out,
                     int* shift) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(near_path)(x, y, z, i, n, w, out, shift);
}

namespace {
// The filter's radius exceeds cutoff + skin by this, relative to it and to the box's
// extent: far more than single precision's rounding of positions within the box.
constexpr double kMarginRadius = 1e-4, kMarginBox = 1e-5;
// The lowest shift's window is widened by this (in box lengths) for the filter's rounding.
constexpr double kFilterSlack = 1e-4;

double filter_radius(const Box& box, double rs) {
  return rs * (1 + kMarginRadius) + kMarginBox * (box.lx + box.ly + box.lz + std::abs(box.xy) +
                                                   std::abs(box.xz) + std::abs(box.yz));
}

// Shifts to try along an axis of edge l: the integers in an open window of width
// 2 r / l, wherever it lies, widened by the slack at both ends.
double shifts_along(double r, double l) { return std::floor(2 * r / l + 2 * kFilterSlack) + 1; }
}  // namespace

int AllPairsSearch::shifts_per_pair(const Box& box, double rs) {
  for (double v : {box.lx, box.ly, box.lz, box.xy, box.xz, box.yz, rs})
    if (!std::isfinite(v)) return 0;
  if (box.lx <= 0 || box.ly <= 0 || box.lz <= 0 || rs <= 0) return 0;
  const double r = filter_radius(box, rs);
  const double k = shifts_along(r, box.lx) * shifts_along(r, box.ly) * shifts_along(r, box.lz);
  return k <= kAllPairsMostShifts ? static_cast<int>(k) : 0;
}

void AllPairsSearch::prepare(const double* x, const double* y, const double* z, int nlocal, int nall,
                             const int* owner, const std::int8_t* n1, const std::int8_t* n2, const std::int8_t* n3,
                             const Box& box, double rs) {
  x_ = x, y_ = y, z_ = z, n1_ = n1, n2_ = n2, n3_ = n3;
  nlocal_ = nlocal;
  rs2_ = rs * rs;
  const double r = filter_radius(box, rs);
  const double l[3] = {box.lx, box.ly, box.lz};
  ImageWindow& w = window_;
  w.lx = static_cast<float>(box.lx), w.ly = static_cast<float>(box.ly), w.lz = static_cast<float>(box.lz);
  w.xy = static_cast<float>(box.xy), w.xz = static_cast<float>(box.xz), w.yz = static_cast<float>(box.yz);
  for (int d = 0; d < 3; ++d) {
    w.inv[d] = static_cast<float>(1 / l[d]);
    w.lower[d] = static_cast<float>(r / l[d] + kFilterSlack);
    w.count[d] = static_cast<int>(shifts_along(r, l[d]));
  }
  w.rs2 = static_cast<float>(r * r);
  const std::size_t padded = static_cast<std::size_t>(nlocal) + kAllPairsPad;
  xf_.assign(padded, 0.0f), yf_.assign(padded, 0.0f), zf_.assign(padded, 0.0f);
  for (int j = 0; j < nlocal; ++j)
    xf_[j] = static_cast<float>(x[j]), yf_[j] = static_cast<float>(y[j]), zf_[j] = static_cast<float>(z[j]);
  // The table of (atom, shift) -> entry over the ghosts' shifts.
  int span[3] = {0, 0, 0};
  for (int k = nlocal; k < nall; ++k) {
    span[0] = std::max(span[0], std::abs(int{n1[k]}));
    span[1] = std::max(span[1], std::abs(int{n2[k]}));
    span[2] = std::max(span[2], std::abs(int{n3[k]}));
  }
  std::copy_n(span, 3, span_);
  for (int d = 0; d < 3; ++d) w.span[d] = static_cast<float>(span[d]);
  stride_ = (2 * span[0] + 1) * (2 * span[1] + 1) * (2 * span[2] + 1);
  terms_.resize(stride_);
  for (int c = -span[2], p = 0; c <= span[2]; ++c)
    for (int b = -span[1]; b <= span[1]; ++b)
      for (int a = -span[0]; a <= span[0]; ++a, ++p)
        terms_[p] = {c * box.xz, b * box.xy, a * box.lx, c * box.yz, b * box.ly, c * box.lz};
  const auto place = [&](int j, int a, int b, int c) {
    return static_cast<std::size_t>(j) * stride_ +
           ((c + span[2]) * (2 * span[1] + 1) + b + span[1]) * (2 * span[0] + 1) + a + span[0];
  };
  entry_.assign(static_cast<std::size_t>(nlocal) * stride_, -1);
  ghost_first_.assign(static_cast<std::size_t>(nlocal) + 1, 0);
  for (int j = 0; j < nlocal; ++j) entry_[place(j, 0, 0, 0)] = j;
  for (int k = nlocal; k < nall; ++k) {
    entry_[place(owner[k], n1[k], n2[k], n3[k])] = k;
    ++ghost_first_[owner[k] + 1];
  }
  for (int j = 0; j < nlocal; ++j) ghost_first_[j + 1] += ghost_first_[j];
  for (int j = 0; j <= nlocal; ++j) ghost_first_[j] += nlocal;
}

int AllPairsSearch::list_of(int i, std::vector<int>& scratch, std::vector<int>& out) const {
  // Scratch: the filter's images (atom and place), then their ghosts.
  const int n = nlocal_;
  const int shifts = window_.count[0] * window_.count[1] * window_.count[2];
  const std::size_t room = static_cast<std::size_t>(n - i) * shifts + kAllPairsPad;
  if (scratch.size() < 3 * room) scratch.resize(3 * room);
  int* const cand = scratch.data();
  int* const place = cand + room;
  int* const ghosts = cand + 2 * room;
  const int m = near_later_atoms(xf_.data(), yf_.data(), zf_.data(), i, n, window_, cand, place);
  const int own = ghost_first_[i + 1] - ghost_first_[i];
  const std::size_t base = out.size();
  out.resize(base + m + own);
  int* const locals = out.data() + base;
  // The images, placed as add_ghosts places them and measured as the binned search
  // measures them (the same bits); those within cutoff + skin that an entry holds go to
  // `locals` (the atoms themselves) or `ghosts`, each ascending. No branch on the
  // unpredictable local-or-ghost decision.
  const double xi = x_[i], yi = y_[i], zi = z_[i];
  int nl = 0, ng = 0;
  for (int s = 0; s < m; ++s) {
    const int j = cand[s], p = place[s];
    const std::array<double, 6>& t = terms_[p];
    const double dz = zi - (z_[j] + t[5]);
    const double dy = yi - ((y_[j] + t[3]) + t[4]);
    const double dx = xi - (((x_[j] + t[0]) + t[1]) + t[2]);
    const int e = entry_[static_cast<std::size_t>(j) * stride_ + p];
    const bool pair = dx * dx + dy * dy + dz * dz < rs2_ && e >= 0;  // no ghost there: no pair of the bins either
    locals[nl] = e;
    ghosts[ng] = e;
    nl += pair && e < n;
    ng += pair && e >= n;
  }
  // Then i's own images (the half list keeps those of positive shift), whose entries
  // follow the later atoms' own and precede their ghosts.
  int* dst = locals + nl;
  for (int k = ghost_first_[i]; k < ghost_first_[i + 1]; ++k) {
    if (!positive_shift(n1_[k], n2_[k], n3_[k])) continue;
    const double dx = xi - x_[k], dy = yi - y_[k], dz = zi - z_[k];
    if (dx * dx + dy * dy + dz * dz < rs2_) *dst++ = k;
  }
  dst = std::copy_n(ghosts, ng, dst);
  const int total = static_cast<int>(dst - locals);
  out.resize(base + total);
  return total;
}

void AllPairsSearch::release() {
  for (auto* v : {&xf_, &yf_, &zf_}) std::vector<float>().swap(*v);
  for (auto* v : {&entry_, &ghost_first_}) std::vector<int>().swap(*v);
  std::vector<std::array<double, 6>>().swap(terms_);
}

std::size_t AllPairsSearch::bytes() const {
  return (xf_.capacity() + yf_.capacity() + zf_.capacity()) * sizeof(float) +
         (entry_.capacity() + ghost_first_.capacity()) * sizeof(int) + terms_.capacity() * sizeof(terms_[0]);
}

}  // namespace mpmx::particles
#endif  // HWY_ONCE
