#pragma once
// A counter-free random stream per (seed, stream id): xoshiro256** seeded through
// SplitMix64, with its own uniform and normal draws so that a stream gives the same
// numbers on every platform and thread count.
#include <array>
#include <cstdint>

namespace mpmx::particles {

class RngStream {
 public:
  RngStream(std::uint64_t seed = 0, std::uint64_t stream = 0);
  std::uint64_t next();
  double uniform();  // [0, 1)
  double normal();   // N(0, 1), Box-Muller
  const std::array<std::uint64_t, 4>& state() const { return s_; }
  void set_state(const std::array<std::uint64_t, 4>& s) { s_ = s; }

 private:
  std::array<std::uint64_t, 4> s_{};
};

}  // namespace mpmx::particles
