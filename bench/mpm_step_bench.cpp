// One continuum step of every shape scheme on the weak shock tube (500 cells, 16 ppc):
// particle-steps per second, for comparing schemes measured in the same run.
#include <benchmark/benchmark.h>

#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/step.hpp"

namespace {

void step_bench(benchmark::State& bs, const char* deck) {
  const auto c = mpmx::app::read_mpm_deck(std::string(MPMX_SOURCE_DIR) + "/examples/" + deck);
  auto s = mpmx::app::make_state(c);
  for (auto _ : bs) mpmx::mpm::step(s, c.dt);
  bs.counters["particle_steps_per_s"] = benchmark::Counter(
      static_cast<double>(s.particles.size()) * bs.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(step_bench, mpm, "S1_mpm_16ppc.toml");
BENCHMARK_CAPTURE(step_bench, cpgimp, "S1_gimp_16ppc.toml");
BENCHMARK_CAPTURE(step_bench, cpdi, "S1_cpdi_16ppc.toml");
BENCHMARK_CAPTURE(step_bench, ddmp, "S1_ddmp_16ppc.toml");
BENCHMARK_CAPTURE(step_bench, ddmp_2ppc_8sub, "S2_ddmp_2ppc_8sub.toml");

BENCHMARK_MAIN();
