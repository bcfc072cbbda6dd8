// ctest-label: validation
// S4 of VALIDATION.md: momentum and energy conservation of the step.
#include <gtest/gtest.h>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

const char* kScheme[] = {"mpm", "ugimp", "cpgimp", "cpdi", "ddmp", "ddmp_subpoints"};

app::MpmConfig free_bar(const std::string& scheme) {
  return test::deck_with(test::example("A1_standing_wave_moving.toml"), [&](toml::table& t) {
    auto& s = *t["scheme"].as_table();
    s.insert_or_assign("name", scheme);
    if (scheme == "ddmp_subpoints") s.insert_or_assign("subpoints", 8);
    t["boundary"].as_table()->insert_or_assign("left", toml::table{{"type", "free"}});
    t["boundary"].as_table()->insert_or_assign("right", toml::table{{"type", "free"}});
    auto& v = *t["initial"]["velocity"].as_table();
    v.insert_or_assign("offset", 0.001);
    v.insert_or_assign("mode", 2);
    t["time"].as_table()->insert_or_assign("dt", 1e-4);
    t["time"].as_table()->insert_or_assign("end", 1.0);  // 10^4 steps
    t.erase("reference");
    t.erase("output");
  });
}

}  // namespace

// S4(b): a free elastic bar keeps its total momentum to 1e-12 over 10^4 steps.
TEST(S4, FreeBarKeepsMomentum) {
  for (const char* s : kScheme) {
    const auto r = test::run(free_bar(s));
    EXPECT_EQ(r.steps, 10000);
    EXPECT_GT(std::abs(r.momentum_initial), 1e-5);
    EXPECT_LT(std::abs(r.momentum_final - r.momentum_initial), 1e-12 * r.momentum_scale) << s;
    EXPECT_EQ(r.boundary_impulse, 0.0) << s;
  }
}

// S4(b): with a drive, momentum changes by exactly the boundary impulse.
TEST(S4, DrivenBarMomentumEqualsBoundaryImpulse) {
  const auto r = test::run(test::deck(test::example("A2_wave_reflection_moving.toml")));
  EXPECT_GT(std::abs(r.boundary_impulse), 1e-5);
  EXPECT_LT(r.momentum_error(), 1e-12 * r.momentum_scale);
}

// S4(c): on the smooth standing wave with moving particles the energy error
// |dK + W| (W = sum V sigma:grad v dt, eq. 4.11) falls about 4x when dx and dt are
// halved (sec. 4.3). Amplitude 0.001 keeps particles within their cells, whose
// crossings are a separate, first-order error of the hat remap (sec. 4.1).
TEST(S4, EnergyErrorSecondOrder) {
  for (const std::string scheme : {"ddmp", "ddmp_subpoints"}) {
    auto error = [&](int k) {
      const auto c = test::deck_with(test::example("A1_standing_wave_moving.toml"), [&](toml::table& t) {
        auto& s = *t["scheme"].as_table();
        s.insert_or_assign("name", scheme);
        if (scheme == "ddmp_subpoints") s.insert_or_assign("subpoints", 4);
        t["grid"].as_table()->insert_or_assign("cells", 50 * k);
        t["initial"]["velocity"].as_table()->insert_or_assign("amplitude", 0.001);
        t["time"].as_table()->insert_or_assign("dt", 0.002 / k);
        t["time"].as_table()->insert_or_assign("end", 2.0);
        t.erase("reference");
        t.erase("output");
      });
      return test::run(c).energy_error();
    };
    const double e1 = error(1), e2 = error(2), e4 = error(4);
    EXPECT_GT(e1 / e2, 3.5) << scheme;
    EXPECT_GT(e2 / e4, 3.5) << scheme;
  }
}
