// ctest-label: crosscheck
// The direct-MD jet through mpmx and through LAMMPS (lammps_jet.hpp: the same atoms,
// velocities, box, piston and potential file, `lmp` from Debian): the binned stress of
// eq. 2.25 on the 2-D grid agrees at step 0 to round-off and over a short run, through
// the impact on the piston, to round-off growth (the 10 K start makes the trajectories
// diverge chaotically over longer times, as the bar's 300 K crosscheck does).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "mpmx/app/md/jet_run.hpp"
#include "mpmx/app/md/lammps_bar.hpp"
#include "mpmx/app/md/lammps_jet.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/jet.hpp"

#include "../md/md_test_util.hpp"

using namespace mpmx::md;
using namespace mpmx::app::md;
namespace fs = std::filesystem;

namespace {

using mpmx::test::have_lmp;

void crosscheck_jet(const std::string& name, double temperature, int ranks, int steps, int every, double step0_rel,
                    double history_gpa) {
  if (!have_lmp()) GTEST_SKIP() << "lmp (LAMMPS) not on PATH";
  JetConfig c;
  c.scale = 0.04;
  c.cells = {400, 200, 3};
  c.temperature = temperature;
  c.seed = 11;
  const double dt = 0.001;
  JetGeometry geo;
  System sys = build_jet(c, mpmx::test::copper(), {}, &geo);
  const BinGrid grid = jet_grid(geo, 16, 4);
  const auto dir = fs::temp_directory_path() / ("mpmx_jet_lammps_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  write_lammps_jet(sys, geo, grid, mpmx::test::copper_spec(), dt, steps, every, 0, dir.string());
  auto bins = [&] {
    return bin_fields(sys.snapshot(), sys.type_mass(), sys.per_atom_virial(), grid).stress;
  };
  std::vector<std::vector<Mat3>> mine{bins()};
  for (int s = 0; s < steps; s += every) {
    sys.advance(every, dt);
    mine.push_back(bins());
  }
  run_lammps(dir.string(), ranks, kLammpsJetInput, kLammpsJetStress);
  const auto theirs = read_lammps_bar_stress((dir / kLammpsJetStress).string(), dt, grid.nx * grid.ny);
  ASSERT_EQ(theirs.size(), mine.size());
  const double to_gpa = mpmx::units::eV_per_A3_in_GPa;
  double smax0 = 0, d0 = 0;
  for (int b = 0; b < grid.nx * grid.ny; ++b) {
    smax0 = std::max(smax0, std::abs(mine[0][b][0] * to_gpa));
    for (int k = 0; k < 9; ++k) d0 = std::max(d0, std::abs(mine[0][b][k] * to_gpa - theirs[0].stress_gpa[b][k]));
  }
  EXPECT_LT(d0, step0_rel * std::max(smax0, 1.0)) << "step 0";
  double dmax = 0, smax = 0;
  for (std::size_t t = 0; t < mine.size(); ++t) {
    EXPECT_EQ(theirs[t].step, static_cast<std::int64_t>(t) * every);
    double d = 0, s = 0;
    for (int b = 0; b < grid.nx * grid.ny; ++b) {
      s = std::max(s, std::abs(mine[t][b][0] * to_gpa));
      for (int k = 0; k < 9; ++k) d = std::max(d, std::abs(mine[t][b][k] * to_gpa - theirs[t].stress_gpa[b][k]));
    }
    std::printf("jet-lammps %s: step %lld  max|sxx| %.3f GPa  max|d sigma| %.3g GPa\n", name.c_str(),
                static_cast<long long>(theirs[t].step), s, d);
    dmax = std::max(dmax, d);
    smax = std::max(smax, s);
  }
  EXPECT_GT(smax, 50.0);  // the shock is there: the comparison is of a loaded state
  EXPECT_LT(dmax, history_gpa);
  fs::remove_all(dir);
}

}  // namespace

// 0 K: the block and the piston alone, one rank.
TEST(jet_lammps, ZeroKelvinImpact) { crosscheck_jet("0K", 0.0, 1, 300, 50, 1e-10, 1e-8); }

// 10 K (started at 20 K, sec. 7.1) on 2 ranks, as `--lammps --ranks 2` runs it.
TEST(jet_lammps, TenKelvinTwoRanks) { crosscheck_jet("10K", 10.0, 2, 200, 50, 1e-10, 1e-7); }
