#include "mpmx/app/dpd/particle_rate.hpp"

#include <chrono>
#include <exception>

#include "mpmx/app/dpd/run.hpp"

namespace mpmx::app::dpd {

double measure_particle_steps_per_second(const DpdConfig& c) {
  constexpr double kSeconds = 0.1;
  constexpr int kMostSteps = 200;
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
