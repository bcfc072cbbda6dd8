#include "mpmx/app/dpd/budget.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/app/dpd/particle_rate.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::app::dpd {

double block_particles(const DpdConfig& c) {
  double particles = 0;
  for (const auto& b : c.blocks)
    particles += b.fcc ? 4.0 * b.cells[0] * b.cells[1] * b.cells[2] : static_cast<double>(b.count);
  return particles;
}

double block_pairs(const DpdConfig& c) {
  const double reach = std::max(cutoff(c.potential), c.params.cutoff) + c.skin;
  const double sphere = (4.0 / 3.0) * M_PI * reach * reach * reach;
  double pairs = 0;
  for (const auto& b : c.blocks) {
    const double n = b.fcc ? 4.0 * b.cells[0] * b.cells[1] * b.cells[2] : static_cast<double>(b.count);
    const double density = b.fcc ? 4.0 / (b.constant * b.constant * b.constant)
                                  : n / (b.size[0] * b.size[1] * b.size[2]);
    pairs += 0.5 * n * std::min(n, sphere * density);  // a block holds no more neighbours than particles
  }
  return pairs;
}

DpdBudget estimate_dpd(const DpdConfig& c) {
  DpdBudget b;
  b.particles = block_particles(c);
  const double steps = static_cast<double>(c.equilibrate ? c.equilibrate_steps : 0) + static_cast<double>(c.steps);
  b.particle_steps = b.particles * steps;
  b.work_key = c.equilibrate && c.equilibrate_steps > 0 ? "equilibrate.steps + run.steps" : "run.steps";
  if (b.seconds() > kDpdTimeRateAboveSeconds)
    if (const double rate = measure_particle_steps_per_second(c); rate > 0) b.rate = rate, b.rate_measured = true;
  return b;
}

void check_dpd_work(const DpdBudget& b, bool force) {
  if (force || !(b.seconds() > kDpdWorkLimitSeconds)) return;
  throw InputError(fmt::format(
      "{}: {:.4g} particles x {:.4g} steps = {:.4g} particle-steps, about {:.3g} days at {:.2g} particle-steps/s "
      "({}): more than the day a run takes without --force",
      b.work_key, b.particles, b.particle_steps / b.particles, b.particle_steps, b.seconds() / 86400.0, b.rate,
      b.rate_measured ? "timed on this core" : "a typical figure"));
}

}  // namespace mpmx::app::dpd
