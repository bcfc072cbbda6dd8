#pragma once
// theta_ij of the random force (seed 004 eq. 2.5): a standard normal number that is a
// pure function of (seed, step, the pair's two particle ids, the periodic image between
// them). Counter-based: SplitMix64's finaliser hashes the key, the k-th 64-bit word of
// the pair's stream is mix64(key + k * golden), and the words feed a ziggurat (Marsaglia
// and Tsang 2000 in Doornik's 2005 ZIGNOR form, 128 layers: one word and one compare for
// 98.8% of the draws, exact tails). So theta_ij does not depend on the thread count,
// the particle order or the order in which pairs are visited, and theta_ij = theta_ji.
#include <array>
#include <cmath>
#include <cstdint>

namespace mpmx::dpd {

inline std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Image code of a ghost shift (n1, n2, n3), each in [-127, 127], as 24 bits.
inline std::uint32_t image_code(int n1, int n2, int n3) {
  return (static_cast<std::uint32_t>(n1 & 0xff) << 16) | (static_cast<std::uint32_t>(n2 & 0xff) << 8) |
         static_cast<std::uint32_t>(n3 & 0xff);
}

// The key of the pair (particle id_i, image (n1, n2, n3) of particle id_j) at `step`:
// the same for (id_j, image -n of id_i). A pair of a particle with its own image keeps
// the sign of the first non-zero shift positive.
inline std::uint64_t pair_key(std::uint64_t seed, std::int64_t step, std::int64_t id_i, std::int64_t id_j, int n1,
                              int n2, int n3) {
  const bool flip = id_i > id_j ||
                    (id_i == id_j && (n1 < 0 || (n1 == 0 && (n2 < 0 || (n2 == 0 && n3 < 0)))));
  const std::int64_t lo = flip ? id_j : id_i, hi = flip ? id_i : id_j;
  const std::uint32_t img = flip ? image_code(-n1, -n2, -n3) : image_code(n1, n2, n3);
  std::uint64_t h = mix64(seed * 0x9e3779b97f4a7c15ULL + 0x632be59bd9b4e019ULL);
  h = mix64(h ^ (static_cast<std::uint64_t>(step) * 0xd1b54a32d192ed03ULL));
  h = mix64(h ^ (static_cast<std::uint64_t>(lo) * 0x8cb92ba72f3d8dd7ULL));
  h = mix64(h ^ (static_cast<std::uint64_t>(hi) * 0xaef17502108ef2d9ULL));
  return mix64(h ^ (static_cast<std::uint64_t>(img) * 0xdb4f0b9175ae2165ULL + 1));
}

namespace detail {

struct Ziggurat {
  static constexpr int kLayers = 128;
  static constexpr double kR = 3.442619855899;       // start of the tail
  static constexpr double kV = 9.91256303526217e-3;  // area of each layer
  std::array<double, kLayers + 1> x{};
  std::array<double, kLayers> ratio{};
  Ziggurat() {
    double f = std::exp(-0.5 * kR * kR);
    x[0] = kV / f;  // the bottom layer with the tail, as a box of equal area
    x[1] = kR;
    x[kLayers] = 0;
    for (int i = 2; i < kLayers; ++i) {
      x[i] = std::sqrt(-2 * std::log(kV / x[i - 1] + f));
      f = std::exp(-0.5 * x[i] * x[i]);
    }
    for (int i = 0; i < kLayers; ++i) ratio[i] = x[i + 1] / x[i];
  }
};

inline const Ziggurat& ziggurat() {
  static const Ziggurat z;
  return z;
}

inline std::uint64_t word(std::uint64_t key, std::uint64_t k) { return mix64(key + k * 0x9e3779b97f4a7c15ULL); }
// (0, 1] from a word.
inline double open_unit(std::uint64_t w) { return static_cast<double>((w >> 11) + 1) * 0x1.0p-53; }

}  // namespace detail

// The standard normal number of a pair key.
inline double pair_normal(std::uint64_t key) {
  const detail::Ziggurat& z = detail::ziggurat();
  for (std::uint64_t k = 0;; ++k) {
    const std::uint64_t w = detail::word(key, k);
    const double u = 2.0 * (static_cast<double>(w >> 11) * 0x1.0p-53) - 1.0;  // [-1, 1)
    const int i = static_cast<int>(w & 0x7f);                                  // layer, bits apart from u's
    if (std::abs(u) < z.ratio[i]) return u * z.x[i];                           // inside the layer's box
    if (i == 0) {                                                              // the tail beyond kR
      for (std::uint64_t t = 1;; t += 2) {
        const double xt = std::log(detail::open_unit(detail::word(key ^ 0x5bd1e995ULL, k * 64 + t))) / z.kR;
        const double yt = std::log(detail::open_unit(detail::word(key ^ 0x5bd1e995ULL, k * 64 + t + 1)));
        if (-2 * yt >= xt * xt) return u < 0 ? xt - z.kR : z.kR - xt;
      }
    }
    const double x = u * z.x[i];  // the wedge: accept under the density
    const double f0 = std::exp(-0.5 * (z.x[i] * z.x[i] - x * x));
    const double f1 = std::exp(-0.5 * (z.x[i + 1] * z.x[i + 1] - x * x));
    const double v = static_cast<double>(detail::word(key ^ 0x2545f4914f6cdd1dULL, k) >> 11) * 0x1.0p-53;
    if (f1 + v * (f0 - f1) < 1.0) return x;
  }
}

}  // namespace mpmx::dpd
