#pragma once
// A count computed in floating point (steps = end / dt, points = cells x per cell), turned
// into an integer only when it is one an int64 holds: a cast or llround of 1e300 is
// undefined behaviour and printed -9223372036854775808 steps.
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

}  // namespace mpmx
