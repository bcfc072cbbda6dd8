#include "mpmx/app/dpd/particle_rate.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <numbers>

#include "mpmx/app/dpd/budget.hpp"
#include "mpmx/app/dpd/run.hpp"
#include "mpmx/dpd/potential/registry.hpp"

namespace mpmx::app::dpd {

double measure_particle_steps_per_second(const DpdConfig& c) {
  constexpr double kSeconds = 0.1;
  constexpr int kMostSteps = 200;
  // Not timed where building the system and its first step alone would take long (the
  // typical figure then stands): more particles or pairs within reach than this.
  constexpr double kMostParticles = 2e5, kMostPairs = 1e6;
  double density = 0;  // particles per cubic Angstrom, the densest block's
  for (const auto& b : c.blocks) {
    const double v = b.size[0] * b.size[1] * b.size[2];
    density = std::max(density, b.fcc ? 4.0 / (b.constant * b.constant * b.constant) : v > 0 ? b.count / v : 0.0);
  }
  const double reach = std::max(mpmx::dpd::cutoff(c.potential), c.params.cutoff) + c.skin;
  const double n = block_particles(c);
  const double pairs = n * density * (4.0 / 3.0) * std::numbers::pi * reach * reach * reach / 2;
  if (!(n <= kMostParticles && pairs <= kMostPairs)) return 0.0;
  try {
    System s = build_system(c, 1);
    const double n = static_cast<double>(s.particles().size());
    if (!(n > 0)) return 0.0;
    s.advance(1, c.dt);
    const auto t0 = std::chrono::steady_clock::now();
    double seconds = 0;
    int steps = 0;
    while (steps < kMostSteps && seconds < kSeconds) {
      s.advance(1, c.dt);
      ++steps;
      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return seconds > 0 ? n * steps / seconds : 0.0;
  } catch (const std::exception&) {
    return 0.0;  // the run itself says what is wrong
  }
}

}  // namespace mpmx::app::dpd
