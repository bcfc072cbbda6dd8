// ctest-label: validation
// The 1-D isothermal shock tube scheme study (dissertation ch. 4), S1-S3 of
// VALIDATION.md, plus the conservation checks S4(a) on every run.
#include <gtest/gtest.h>

#include <map>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

struct Outcome {
  double l1 = 0.0, peak = 0.0;
};

// Runs an example deck once per test binary and remembers it.
Outcome outcome(const std::string& name) {
  static std::map<std::string, Outcome> cache;
  if (auto it = cache.find(name); it != cache.end()) return it->second;
  const auto r = test::run(test::deck(test::example(name + ".toml")));
  // S4(a): internal forces sum to zero at every step, nodal mass equals particle mass.
  EXPECT_LT(r.max_force_sum, 1e-13) << name;
  EXPECT_NEAR(r.mass_nodes, r.mass_particles, 1e-12 * r.mass_particles) << name;
  // Momentum changes only by the wall impulse; 1e-11 leaves room for the round-off of
  // summing up to 64,000 particle momenta.
  EXPECT_LT(r.momentum_error(), 1e-11 * r.momentum_scale) << name;
  Outcome o{r.errors.at("pressure").l1, r.errors.at("pressure").peak};
  cache[name] = o;
  return o;
}

double l1(const std::string& name) { return outcome(name).l1; }

}  // namespace

// S1: the original MPM cannot carry the weak waves with few particles per cell.
TEST(S1, OriginalMpmFails) {
  for (int ppc : {2, 8, 16, 32, 64}) EXPECT_GT(l1("S1_mpm_" + std::to_string(ppc) + "ppc"), 0.5) << ppc;
}

// S1: GIMP and CPDI get worse from 8 to 64 particles per cell (finite domains shrink and
// the particle Courant number grows, sec. 4.2).
TEST(S1, GimpAndCpdiWorsenWithMoreParticles) {
  for (const std::string s : {"gimp", "cpdi"}) {
    const double e8 = l1("S1_" + s + "_8ppc"), e16 = l1("S1_" + s + "_16ppc");
    const double e32 = l1("S1_" + s + "_32ppc"), e64 = l1("S1_" + s + "_64ppc");
    EXPECT_GT(e64, 1.05 * e8) << s;
    EXPECT_GT(e32, e16) << s;
    EXPECT_GT(e64, e32) << s;
    EXPECT_LT(e8, 0.05) << s;  // and are good with few particles
  }
}

// S1: DDMP improves monotonically as particles are added (fig. 4.6) and is worse than
// GIMP/CPDI at 8 ppc (sec. 4.2).
TEST(S1, DdmpImprovesMonotonically) {
  const double e8 = l1("S1_ddmp_8ppc"), e16 = l1("S1_ddmp_16ppc");
  const double e32 = l1("S1_ddmp_32ppc"), e64 = l1("S1_ddmp_64ppc");
  EXPECT_GT(e8, e16);
  EXPECT_GT(e16, e32);
  EXPECT_GT(e32, e64);
  EXPECT_GT(e8, l1("S1_cpdi_8ppc"));
}

// S2: n particles x m sub-points is within 15% of DDMP with n*m particles per cell.
TEST(S2, SubPointsMatchManyParticles) {
  for (int n : {2, 4})
    for (int m : {8, 16, 32}) {
      const double sub = l1("S2_ddmp_" + std::to_string(n) + "ppc_" + std::to_string(m) + "sub");
      const double many = l1("S1_ddmp_" + std::to_string(n * m) + "ppc");
      EXPECT_NEAR(sub / many, 1.0, 0.15) << n << " ppc x " << m << " sub-points";
    }
}

// S3: strong shock (p_left / p_right = 4): 2 ppc x 16 sub-points within 15% of 32 ppc;
// CPDI shows the larger noise of fig. 4.9b.
TEST(S3, StrongShockSubPoints) {
  const double sub = l1("S3_ddmp_2ppc_16sub"), many = l1("S3_ddmp_32ppc");
  EXPECT_NEAR(sub / many, 1.0, 0.15);
  EXPECT_GT(outcome("S3_cpdi_32ppc").peak, outcome("S3_ddmp_32ppc").peak);
}
