// ctest-label: crosscheck
// NPT at 300 K and 0 GPa, and the Hugoniostat, against LAMMPS's fix npt and fix nphug (issue 47): a 500-atom Mishin copper
// box, the same damping periods (0.1 ps, 1 ps), 20 ps each, the last 15 ps sampled every
// 20 steps. The mean pressure is within three standard errors of zero in both, and the
// mean lattice constant and temperature agree within three standard errors of their
// difference (standard errors from ten block means: the samples are correlated).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <vector>

#include <fmt/format.h>

#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/particles/lattice.hpp"

#include "../md/hugoniostat_run.hpp"

using namespace mpmx::md;
namespace fs = std::filesystem;

namespace {

using Stats = mpmx::test::BlockStats;
constexpr auto stats = mpmx::test::block_stats;

constexpr int kSteps = 20000, kEvery = 20, kSkip = 5000;

struct Series {
  std::vector<double> t, p, a;  // K, GPa, A
};

Series run_lammps(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "in.npt") << fmt::format(
      "units metal\natom_style atomic\nlattice fcc 3.615\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\n"
      "create_atoms 1 box\nmass 1 63.546\npair_style eam/alloy\npair_coeff * * {} Cu\n"
      "velocity all create 600.0 4321 mom yes rot no dist gaussian\nneighbor 1.0 bin\ntimestep 0.001\n"
      "fix 1 all npt temp 300 300 0.1 iso 0 0 1.0\nthermo_style custom step temp press lx\nthermo {}\nrun {}\n",
      mpmx::test::kCuMishin, kEvery, kSteps);
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.npt -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("lmp failed in " + dir.string());
  std::ifstream log(dir / "log.lammps");
  Series s;
  std::string line;
  bool rows = false;
  while (std::getline(log, line)) {
    std::istringstream in(line);
    std::string first;
    in >> first;
    if (first == "Step") {
      rows = true;
      continue;
    }
    if (!rows) continue;
    double step, t, p, lx;
    std::istringstream r(line);
    if (!(r >> step >> t >> p >> lx)) {
      rows = false;
      continue;
    }
    if (step < kSkip + kEvery) continue;
    s.t.push_back(t), s.p.push_back(p * 1e-4), s.a.push_back(lx / 5);
  }
  return s;
}

Series run_mine() {
  System s(fcc(5, 5, 5, 3.615), mpmx::test::copper());
  s.thermalize(300, 3, 0);  // 600 K at the start, as LAMMPS's velocity create above
  NoseHooverOptions o;
  o.temperature = 300, o.barostat = true, o.t_damp = 0.1, o.p_damp = 1.0;
  NoseHoover nh(o, s);
  Series r;
  for (int step = kEvery; step <= kSteps; step += kEvery) {
    s.advance_coupled(kEvery, 0.001, nh);
    if (step < kSkip + kEvery) continue;
    const Mat3 g = s.stress_gpa();
    r.t.push_back(s.temperature()), r.p.push_back(-(g[0] + g[4] + g[8]) / 3), r.a.push_back(s.box().lx / 5);
  }
  return r;
}

}  // namespace

TEST(NptLammps, SameStateAtThreeHundredKelvinAndZeroPressure) {
  if (!mpmx::test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  const auto dir = fs::temp_directory_path() / ("mpmx_npt_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const Series L = run_lammps(dir), M = run_mine();
  ASSERT_EQ(L.a.size(), M.a.size());
  const char* names[3] = {"T (K)", "P (GPa)", "a (A)"};
  const std::vector<double>* ms[3] = {&M.t, &M.p, &M.a};
  const std::vector<double>* ls[3] = {&L.t, &L.p, &L.a};
  Stats m[3], l[3];
  for (int k = 0; k < 3; ++k) {
    m[k] = stats(*ms[k]), l[k] = stats(*ls[k]);
    std::printf("NPT vs LAMMPS %-7s mpmx %.5f +- %.5f  LAMMPS %.5f +- %.5f\n", names[k], m[k].mean, m[k].sem,
                l[k].mean, l[k].sem);
  }
  EXPECT_LT(std::abs(m[1].mean), 3 * m[1].sem);
  EXPECT_LT(std::abs(l[1].mean), 3 * l[1].sem);
  for (int k : {0, 2})
    EXPECT_LT(std::abs(m[k].mean - l[k].mean), 3 * std::hypot(m[k].sem, l[k].sem)) << names[k];
  fs::remove_all(dir);
}

// The Hugoniostat (fix nphug) at J1's plateau, 172 GPa along x, from 10 K: the shocked
// volume and temperature within three standard errors of their difference.
TEST(NphugLammps, SameShockedStateAtJ1Plateau) {
  using mpmx::test::kHugEvery, mpmx::test::kHugSteps;
  if (!mpmx::test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  const auto dir = fs::temp_directory_path() / ("mpmx_nphug_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "in.hug") << fmt::format(
      "units metal\natom_style atomic\nlattice fcc 3.6155\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\n"
      "create_atoms 1 box\nmass 1 63.546\npair_style eam/alloy\npair_coeff * * {} Cu\n"
      "velocity all create 20.0 4321 mom yes rot no dist gaussian\nneighbor 1.0 bin\ntimestep 0.001\n"
      "fix 0 all nve\nrun 2000\nunfix 0\nfix 1 all nphug temp 1.0 1.0 0.1 x 1720000 1720000 1.0\n"
      "thermo_style custom step temp pxx vol\nthermo {}\nrun {}\n",
      mpmx::test::kCuMishin, kHugEvery, kHugSteps);
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.hug -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "lmp failed in " << dir;
  std::ifstream log(dir / "log.lammps");
  std::vector<double> ratio, t;
  std::string line;
  bool rows = false;
  double v0 = 0;
  while (std::getline(log, line)) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string x; in >> x;) w.push_back(x);
    if (w.size() == 4 && w[0] == "Step" && w[2] == "Pxx") {
      rows = true;
      continue;
    }
    if (!rows) continue;
    if (w.size() != 4 || w[0].find_first_not_of("0123456789") != std::string::npos) {
      rows = false;
      continue;
    }
    const double step = std::stod(w[0]) - 2000, vol = std::stod(w[3]);
    if (step == 0) v0 = vol;
    if (2 * step > kHugSteps) ratio.push_back(vol / v0), t.push_back(std::stod(w[1]));
  }
  ASSERT_EQ(ratio.size(), static_cast<std::size_t>(kHugSteps / kHugEvery / 2));
  const auto lr = mpmx::test::block_stats(ratio), lt = mpmx::test::block_stats(t);
  const mpmx::test::Shocked m = mpmx::test::hugoniostat(3.6155, 10, 172);
  std::printf("nphug vs LAMMPS at 172 GPa: V/V0 %.5f +- %.5f (LAMMPS %.5f +- %.5f), T %.1f +- %.1f K (%.1f +- %.1f)\n",
              m.ratio.mean, m.ratio.sem, lr.mean, lr.sem, m.t.mean, m.t.sem, lt.mean, lt.sem);
  EXPECT_LT(std::abs(m.ratio.mean - lr.mean), 3 * std::hypot(m.ratio.sem, lr.sem));
  EXPECT_LT(std::abs(m.t.mean - lt.mean), 3 * std::hypot(m.t.sem, lt.sem));
  fs::remove_all(dir);
}
