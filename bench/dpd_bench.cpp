// DPD speed against LAMMPS in one invocation (issue 16): the seed's system size, 12,000
// Cu mesoparticles (fcc 30 x 10 x 10 cells of 2a = 7.23 Angstrom, periodic), Morse
// rc = 12 Angstrom shifted, skin 1 Angstrom, dt = 5 fs, started at 596 K.
//
// Prints particle-steps per second of mpmx's DPDE (Shardlow, the seed's gamma = 0.2
// amu/ps), isothermal DPD (velocity Verlet with dissipative and random forces) and the
// conservative part alone (gamma = 0), on 1 and 2 threads; then LAMMPS on the same
// particles, cutoff, skin and steps. Debian's lmp has neither DPD-BASIC (pair dpd) nor
// DPD-REACT (fix shardlow), so its figure is pair morse + fix nve, the conservative part
// alone: the ratio of mpmx's full DPDE to it is a lower bound of the ratio to LAMMPS's
// DPDE (which adds the stochastic sweep to the same work).
//
// Every figure is the best of `repeats` runs (default 3), LAMMPS's too.
// Usage: dpd_bench [nx ny nz [steps [repeats]]]   (from the build: bench/dpd_bench)
// Timing is printed, never asserted.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "mpmx/app/dpd/lammps_deck.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/setup.hpp"
#include "mpmx/dpd/system.hpp"

using namespace mpmx;

namespace {

struct Case {
  const char* name;
  bool dpde;
  dpd::Integrator integrator;
  double gamma;
};

dpd::System make(const std::array<int, 3>& cells, const Case& c, int threads) {
  const double a = 7.23;
  dpd::Particles p = dpd::fcc_block(cells, a, {0, 0, 0}, 8 * 63.546, 0, 1);
  dpd::maxwell_velocities(p, 596.0, 2014);
  const double cv = 21 * units::boltzmann_eV_per_K;
  for (auto& u : p.u) u = cv * 298.0;
  dpd::MorsePotential m;
  m.d0 = 2.7432, m.alpha = 0.6794, m.r0 = 5.732, m.rc = 12.0, m.shift = true;
  m.update_offset();
  dpd::DpdParams par;
  par.energy_conserving = c.dpde;
  par.integrator = c.integrator;
  par.gamma = c.gamma;
  par.cutoff = 12.0;
  par.temperature = 298.0;
  par.heat_capacity = cv;
  par.seed = 7;
  dpd::Domain d;
  d.box.lx = cells[0] * a, d.box.ly = cells[1] * a, d.box.lz = cells[2] * a;
  return dpd::System(p, d, m, par, {.skin = 1.0, .threads = threads});
}

// Best of `repeats` runs (a shared machine's load only ever slows a run down).
double rate(const std::array<int, 3>& cells, const Case& c, int threads, int steps, int repeats) {
  double best = 0;
  for (int r = 0; r < repeats; ++r) {
    dpd::System s = make(cells, c, threads);
    s.advance(5, 0.005);  // first forces, buffers sized
    const auto t0 = std::chrono::steady_clock::now();
    s.advance(steps, 0.005);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    best = std::max(best, static_cast<double>(s.particles().size()) * steps / secs);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::array<int, 3> cells{30, 10, 10};
  int steps = 300;
  if (argc >= 4)
    for (int d = 0; d < 3; ++d) cells[d] = std::atoi(argv[1 + d]);
  if (argc >= 5) steps = std::atoi(argv[4]);
  const int repeats = argc >= 6 ? std::max(1, std::atoi(argv[5])) : 3;
  const long n = 4L * cells[0] * cells[1] * cells[2];
  std::printf("DPD bench: %ld Cu mesoparticles (fcc %d x %d x %d, a = 7.23 A, periodic), Morse rc = 12 A, "
              "skin 1 A, dt = 5 fs, %d steps, best of %d\n",
              n, cells[0], cells[1], cells[2], steps, repeats);

  const Case cases[] = {
      {"DPDE, Shardlow, gamma 0.2 amu/ps", true, dpd::Integrator::shardlow, 0.2},
      {"isothermal DPD, velocity Verlet", false, dpd::Integrator::velocity_verlet, 0.2},
      {"conservative only (gamma 0), velocity Verlet", false, dpd::Integrator::velocity_verlet, 0.0},
  };
  double r1[3], r2[3];
  for (int k = 0; k < 3; ++k) {
    r1[k] = rate(cells, cases[k], 1, steps, repeats);
    r2[k] = rate(cells, cases[k], 2, steps, repeats);
    std::printf("mpmx %-46s 1 thread %10.4g  2 threads %10.4g particle-steps/s  (x%.2f)\n", cases[k].name, r1[k],
                r2[k], r2[k] / r1[k]);
  }

  if (!app::dpd::lammps_available()) {
    std::printf("LAMMPS: lmp is not installed (apt-get install lammps): no ratio\n");
    return 0;
  }
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("mpmx_dpd_bench_" + std::to_string(getpid()))).string();
  const dpd::System s = make(cells, cases[2], 1);
  app::dpd::write_lammps_dpd(s, {.steps = steps + 5, .dt = 0.005, .dump_forces = false}, dir);
  double loop = 1e300;
  for (int r = 0; r < repeats; ++r) loop = std::min(loop, app::dpd::run_lammps_dpd(dir).loop_seconds);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  const double lmp = static_cast<double>(n) * (steps + 5) / loop;
  std::printf("LAMMPS pair morse + fix nve (conservative only), 1 process %10.4g particle-steps/s\n", lmp);
  std::printf("ratio mpmx / LAMMPS, conservative part, 1 thread: %.2f (2 threads: %.2f)\n", r1[2] / lmp, r2[2] / lmp);
  std::printf("ratio mpmx DPDE (Shardlow) / LAMMPS conservative only, 1 thread: %.2f (2 threads: %.2f); a lower "
              "bound of the ratio to LAMMPS's DPDE\n",
              r1[0] / lmp, r2[0] / lmp);
  std::printf("ratio mpmx isothermal DPD / LAMMPS conservative only, 1 thread: %.2f (2 threads: %.2f)\n", r1[1] / lmp,
              r2[1] / lmp);
  return 0;
}
