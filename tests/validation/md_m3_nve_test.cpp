// ctest-label: slow
// M3: NVE energy conservation, 500 Cu atoms at 300 K (initialised at 600 K, section 6.2),
// dt = 1 fs, 10 ps: the drift (least-squares slope times the run length) stays below
// 1e-5 eV/atom.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

using namespace mpmx::md;

TEST(M3, NveDriftBelow1e5PerAtomOver10ps) {
  EamSpec spec;
  spec.file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";
  System s(fcc(5, 5, 5, 3.615), Potential(spec));
  s.thermalize(300, 2024, 0);
  const double n = static_cast<double>(s.atoms().size());
  std::vector<double> t, e;
  for (int k = 0; k <= 1000; ++k) {
    if (k) s.advance(10, 0.001);
    t.push_back(s.time());
    e.push_back((s.potential_energy() + s.kinetic_energy()) / n);
  }
  double mt = 0, me = 0;
  for (std::size_t k = 0; k < t.size(); ++k) mt += t[k] / t.size(), me += e[k] / e.size();
  double sxy = 0, sxx = 0, worst = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    sxy += (t[k] - mt) * (e[k] - me);
    sxx += (t[k] - mt) * (t[k] - mt);
    worst = std::max(worst, std::abs(e[k] - e[0]));
  }
  const double drift = sxy / sxx * (t.back() - t.front());
  std::printf("M3: drift %.3g eV/atom over %.1f ps, max |E - E0| %.3g eV/atom, T = %.1f K\n", drift, t.back(),
              worst, s.temperature());
  EXPECT_LT(std::abs(drift), 1e-5);
}
