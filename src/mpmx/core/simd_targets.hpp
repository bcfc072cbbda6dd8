#pragma once
// The vector paths compiled into the vector kernels (Google Highway's targets: the 1-D
// continuum's, mpm/fused1d, and the MD engine's, md/potential/eam_one_type and
// md/neighbor_search): every file that compiles or dispatches to them includes this
// before any Highway header, so that they all agree. Left out: SSSE3 (the machines with it but without SSE4.2 and AES are
// fifteen years old; they take the scalar path), AVX3_DL (nothing more for doubles), and
// the scalable-vector targets (SVE, RVV): the kernels keep vectors in arrays, which needs
// a size known at compile time.
#if defined(HIGHWAY_HWY_DETECT_TARGETS_H_)
#error "include mpmx/core/simd_targets.hpp before any Highway header"
#endif
#define HWY_DISABLED_TARGETS \
  (HWY_SSSE3 | HWY_AVX3_DL | HWY_SVE | HWY_SVE2 | HWY_SVE_256 | HWY_SVE2_128 | HWY_RVV)
