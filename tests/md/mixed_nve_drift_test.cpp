// ctest-label: slow
// Mixed precision against double over a long NVE run: a 500-atom copper box at 300 K for
// 1e5 steps of 1 fs (100 ps). Float pair arithmetic puts a small error in every force;
// leapfrog keeps the energy bounded all the same, and the mixed run must drift no more
// than the double one does (docs/theory.md, "Mixed precision", gives the figures).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;

namespace {

struct Drift {
  double worst = 0;  // the largest |E - E0| seen, eV/atom
  double slope = 0;  // least-squares slope of E(t), eV/atom per ns
};

Drift nve_drift(bool mixed) {
  SystemOptions o;
  o.mixed_precision = mixed;
  System s(fcc(5, 5, 5, 3.615), mpmx::test::copper(), o);
  s.thermalize(300, 11, 0);
  const double n = static_cast<double>(s.atoms().size());
  s.advance(2000, 0.001);  // equipartition first
  const double e0 = mpmx::test::total_energy(s) / n;
  Drift d;
  double st = 0, se = 0, stt = 0, ste = 0;
  constexpr int kRecords = 100;
  for (int k = 1; k <= kRecords; ++k) {
    s.advance(1000, 0.001);
    const double e = mpmx::test::total_energy(s) / n - e0, t = 1e-3 * k;  // ns
    d.worst = std::max(d.worst, std::abs(e));
    st += t, se += e, stt += t * t, ste += t * e;
  }
  d.slope = (kRecords * ste - st * se) / (kRecords * stt - st * st);
  return d;
}

}  // namespace

TEST(MixedPrecision, NveDriftNoWorseThanDouble) {
  const Drift d = nve_drift(false), m = nve_drift(true);
  std::printf("500 atoms, 300 K, 1e5 steps of 1 fs: |E - E0| at most %.3g eV/atom (double), %.3g (mixed); "
              "drift %.3g and %.3g eV/atom/ns\n",
              d.worst, m.worst, d.slope, m.slope);
  // Leapfrog's bounded energy error of the time step is the same in both: mixed stays
  // within twice double's largest excursion, and its drift over the whole 0.1 ns run is
  // smaller than that excursion (a drift, not the bounded oscillation, would pass it).
  EXPECT_LT(m.worst, 2.0 * d.worst);
  EXPECT_LT(std::abs(m.slope) * 0.1, d.worst);
}
