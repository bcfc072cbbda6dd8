// The neighbour-list build's candidate filter, compiled once per vector path of
// core/simd_targets.hpp (hwy/foreach_target.h includes this file again for each). Each
// vector tests a vector's worth of one run's candidates (a partial one at the run's end,
// the rest masked off) and writes the kept entries packed (Highway's CompressBitsStore):
// no branch depends on the in/out decisions. Compiled with -ffp-contract=off
// (CMakeLists.txt): r^2 has the scalar path's bits on every path.

// clang-format off
#include "mpmx/core/simd_targets.hpp"  // first: the paths to compile
// clang-format on

#include "mpmx/particles/neighbor_search.hpp"

#include <cstddef>
#include <cstdint>

#include "mpmx/core/isa.hpp"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "mpmx/particles/neighbor_search.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace mpmx::particles::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

int search_runs_path(const BinnedEntries& b, const int* run, int nrun, double xi, double yi, double zi,
                     double rs2, int twice_i, int* out) {
  // Eight doubles a vector at most (a full AVX-512 register), their entries as int32.
  const hn::CappedTag<double, 8> d;
  const hn::Rebind<int32_t, decltype(d)> di;
  const std::size_t N = hn::Lanes(d);
  const auto vx = hn::Set(d, xi), vy = hn::Set(d, yi), vz = hn::Set(d, zi), cut = hn::Set(d, rs2);
  const auto past = hn::Set(d, static_cast<double>(twice_i));  // keys compared as doubles (exact)
  std::size_t n = 0;
  for (int r = 0; r < nrun; ++r) {
    const std::size_t s1 = static_cast<std::size_t>(run[2 * r + 1]);
    for (std::size_t s = static_cast<std::size_t>(run[2 * r]); s < s1; s += N) {
      const auto dx = hn::Sub(vx, hn::LoadU(d, b.x + s));
      const auto dy = hn::Sub(vy, hn::LoadU(d, b.y + s));
      const auto dz = hn::Sub(vz, hn::LoadU(d, b.z + s));
      const auto rsq = hn::Add(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)), hn::Mul(dz, dz));
      const auto near = hn::And(hn::Lt(rsq, cut), hn::FirstN(d, s1 - s));
      const auto keep = hn::And(near, hn::Gt(hn::PromoteTo(d, hn::LoadU(di, b.key + s)), past));
      // The mask as bits carries over to the entries' narrower lanes.
      uint8_t bits[8] = {};
      hn::StoreMaskBits(d, keep, bits);
      n += hn::CompressBitsStore(hn::LoadU(di, b.entry + s), bits, di, out + n);
    }
  }
  return static_cast<int>(n);
}

}  // namespace mpmx::particles::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace mpmx::particles {

HWY_EXPORT(search_runs_path);

int search_runs(const BinnedEntries& b, const int* run, int nrun, double xi, double yi, double zi, double rs2,
                int twice_i, int* out) {
  isa_prepare();
  return HWY_DYNAMIC_DISPATCH(search_runs_path)(b, run, nrun, xi, yi, zi, rs2, twice_i, out);
}

}  // namespace mpmx::particles
#endif  // HWY_ONCE
