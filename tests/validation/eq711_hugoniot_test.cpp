// ctest-label: validation
// Eq. 7.11 on a strong shock (issue 55): a 1-D DDMP-MD copper bar (80 points of
// 256-atom boxes from 10 K) driven at 2.5 km/s by a piston, with energy consistency, at
// the continuum steps 0.01 and 0.002 ps (10 and 2 MD steps a macro step). At 2 ps the
// points behind the front (sigma_xx below -100 GPa) sit on the Hugoniostat's state at
// up = 2.5 km/s (172 GPa, V/V0 0.6686: density 13.365, docs/validation.md) in stress
// (within its ringing) and density, and their temperature no longer grows as the step shrinks: before the removal
// a cold box cannot take was carried (theory.md), the two steps gave 3,495 and 11,758 K;
// now 2,063 and 2,955 K against the Hugoniot's 3,333 K, which they miss by what the
// continuum's own transfers dissipate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../md/md_test_util.hpp"
#include "cli_util.hpp"

namespace eq711_hugoniot {

struct Plateau {
  double temperature = 0, stress = 0, density = 0;
  std::size_t points = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

Plateau run_bar(double dt) {
  const std::string deck = fmt::format(R"([case]
id = "eq711_bar"
units = "nm_ps_GPa"
[grid]
upper = 56.392831
cells = 80
[particles]
per_cell = 1
[scheme]
name = "ddmp_subpoints"
subpoints = 8
update_velocity = "updated"
[material]
model = "md_closure"
[material.potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
[material.md]
cells = 4
temperature = 10.0
seed = 1
dt = 0.001
energy_consistency = true
[boundary]
left = {{ type = "piston", velocity = 2.5 }}
[viscosity]
linear = 0.5
[time]
dt = {}
end = 2.0
[output]
times = [2.0]
plot = false
)",
                                       dt);
  const std::string name = fmt::format("eq711_{}", dt);
  const auto path = mpmx::test::scratch_file(name + ".toml", deck);
  const auto out = mpmx::test::scratch_root() / name;
  const auto r = mpmx::test::run_cli("run " + path.string() + " --out " + out.string() + " -q --threads 1");
  EXPECT_EQ(r.status, 0) << r.output;
  std::ifstream csv(out / "particles.csv");
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> names;
  {
    std::stringstream h(line);
    for (std::string f; std::getline(h, f, ',');) names.push_back(f);
  }
  auto col = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  const auto t = col("time"), s = col("stress"), rho = col("density"), T = col("temperature");
  std::vector<double> ts, ss, rs;
  while (std::getline(csv, line)) {
    std::vector<double> v;
    std::stringstream row(line);
    for (std::string f; std::getline(row, f, ',');) v.push_back(std::strtod(f.c_str(), nullptr));
    if (v.size() != names.size() || v[t] < 2.0 - 1e-9 || !(v[s] < -100.0)) continue;
    ts.push_back(v[T]), ss.push_back(v[s]), rs.push_back(v[rho]);
  }
  return {median(ts), median(ss), median(rs), ts.size()};
}

TEST(Eq711Hugoniot, ShockedBoxesOnTheHugoniotWhateverTheStep) {
  const Plateau coarse = run_bar(0.01), fine = run_bar(0.002);
  for (const Plateau* p : {&coarse, &fine})
    std::printf("dt %s: %zu points, median %.0f K, %.1f GPa, density %.3f (Hugoniot: 3333 K, -172 GPa, 13.365)\n",
                p == &coarse ? "0.01" : "0.002", p->points, p->temperature, p->stress, p->density);
  for (const Plateau* p : {&coarse, &fine}) {
    ASSERT_GE(p->points, 10u);
    // The plateau's 20 points ring by a few percent about it: its median moved between
    // -161.5 and -170.5 GPa with changes elsewhere in the code (the density far less).
    EXPECT_NEAR(p->stress, -172.0, 0.08 * 172.0);
    EXPECT_NEAR(p->density, 13.365, 0.03 * 13.365);
    EXPECT_GT(p->temperature, 1500.0);  // the viscosity's heat is in: off, the boxes stay below 500 K
    EXPECT_LT(p->temperature, 3700.0);  // no ratchet: dropped removals gave 11,758 K at dt 0.002
  }
  EXPECT_LT(fine.temperature / coarse.temperature, 1.6);  // 3.4 with the removals dropped
}

}  // namespace eq711_hugoniot
