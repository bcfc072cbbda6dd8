// Thermal initialisation (section 6.2) and energy injection (eq. 7.11) of an md::System:
// Maxwell at twice the target with zero momentum, streams independent of threads.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;

namespace {
using mpmx::test::copper;
using mpmx::test::total_energy;
}  // namespace

TEST(Thermal, MaxwellAtTwiceTargetWithZeroMomentum) {
  System s(fcc(5, 5, 5, 3.615), copper());
  s.thermalize(300, 11, 3);
  EXPECT_NEAR(s.temperature(), 600.0, 1e-9);
  double p[3] = {0, 0, 0};
  for (std::size_t i = 0; i < s.atoms().size(); ++i)
    p[0] += s.atoms().vx[i], p[1] += s.atoms().vy[i], p[2] += s.atoms().vz[i];
  for (double c : p) EXPECT_NEAR(c, 0.0, 1e-10);
  // Isotropic: each direction carries about a third of the kinetic energy.
  double k[3] = {0, 0, 0};
  for (std::size_t i = 0; i < s.atoms().size(); ++i)
    k[0] += std::pow(s.atoms().vx[i], 2), k[1] += std::pow(s.atoms().vy[i], 2), k[2] += std::pow(s.atoms().vz[i], 2);
  const double sum = k[0] + k[1] + k[2];
  for (double c : k) EXPECT_NEAR(c / sum, 1.0 / 3.0, 0.08);  // 4 sigma for 500 atoms
  // Relaxation at zero strain rate: equipartition brings T near the target.
  s.advance(2000, 0.001);
  std::printf("after 2 ps: T = %.1f K\n", s.temperature());
  EXPECT_NEAR(s.temperature(), 300.0, 60.0);
}

TEST(Thermal, StreamsAreReproducibleAndThreadIndependent) {
  const System base(fcc(3, 3, 3, 3.615), copper());
  auto run = [&](std::uint64_t id) {
    System s = base;
    s.thermalize(500, 99, id);
    s.advance(50, 0.001);
    return s;
  };
  const System a = run(1);
  System b = base, c = base;
  std::thread t1([&] { b = run(1); });
  std::thread t2([&] { c = run(2); });
  t1.join();
  t2.join();
  for (std::size_t i = 0; i < a.atoms().size(); ++i) {
    ASSERT_EQ(a.atoms().x[i], b.atoms().x[i]);
    ASSERT_EQ(a.atoms().vx[i], b.atoms().vx[i]);
  }
  EXPECT_NE(a.atoms().vx[0], c.atoms().vx[0]);
}

TEST(Thermal, EnergyInjectionAddsExactlyThatEnergy) {
  System s(fcc(3, 3, 3, 3.615), copper());
  s.add_energy(0.5);  // a box at rest
  EXPECT_NEAR(s.thermal_kinetic_energy(), 0.5, 1e-12);
  s.thermalize(100, 1, 1);
  const double e0 = total_energy(s);
  s.add_energy(0.25);
  EXPECT_NEAR(total_energy(s) - e0, 0.25, 1e-12);
  s.add_energy(-0.1);
  EXPECT_NEAR(total_energy(s) - e0, 0.15, 1e-12);
  EXPECT_THROW(s.add_energy(-1e3), mpmx::RunError);
}
