#pragma once
// Wall time per phase of the stencil step (run.json "phases"): where a run's time goes,
// and, set beside a run on other threads, which phase scales least. Two clock reads per
// phase, a few tens of nanoseconds against steps of a millisecond.
#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace mpmx::mpm {

enum class Phase : std::size_t {
  stencil,   // nearest nodes, S_ip, G_ip
  p2g,       // mass, momentum, force (and DDMP's smoothed force)
  grid,      // small-mass distribution, the solve, boundaries
  g2p,       // particle velocities, positions, velocity gradients (MUSL's re-map too)
  material,  // work and volumes, the stress update (MD boxes included), viscosity
  count
};

inline constexpr std::array<std::string_view, static_cast<std::size_t>(Phase::count)> kPhaseNames{
    "stencil", "p2g", "grid", "g2p", "material"};

struct PhaseTimes {
  using Clock = std::chrono::steady_clock;
  std::array<double, static_cast<std::size_t>(Phase::count)> seconds{};
  Clock::time_point last;

  void start() { last = Clock::now(); }
  // The time since the last start or lap, to `phase`.
  void lap(Phase phase) {
    const Clock::time_point now = Clock::now();
    seconds[static_cast<std::size_t>(phase)] += std::chrono::duration<double>(now - last).count();
    last = now;
  }
  double total() const {
    double t = 0.0;
    for (double s : seconds) t += s;
    return t;
  }
};

}  // namespace mpmx::mpm
