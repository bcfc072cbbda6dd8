#pragma once
// Counts that cannot wrap: one computed in floating point (steps = end / dt) turned into
// an integer only when an int64 holds it (a cast or llround of 1e300 is undefined and
// printed -9223372036854775808 steps), and a sum of two counts checked the same way.
#include <cmath>
#include <cstdint>
#include <optional>

namespace mpmx {

// `x` rounded to the nearest whole number, when finite and within [0, 2^63); else none.
inline std::optional<std::int64_t> rounded_count(double x) {
  constexpr double kTwo63 = 9223372036854775808.0;
  if (!(x >= 0) || !(std::round(x) < kTwo63)) return std::nullopt;
  return static_cast<std::int64_t>(std::llround(x));
}

// a + b when an int64 holds it; else none (two step counts of 2^62 each wrap negative).
inline std::optional<std::int64_t> checked_sum(std::int64_t a, std::int64_t b) {
  std::int64_t s = 0;
  if (__builtin_add_overflow(a, b, &s)) return std::nullopt;
  return s;
}

}  // namespace mpmx
