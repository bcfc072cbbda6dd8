// The work-energy balance's warning (issue 53, item 7): a run whose balance misses by
// more than 5% of the energy in play says so on the terminal, naming the figure (the
// original MPM's shock tube, S1_mpm_64ppc); a run that holds it says nothing (A1).
#include <gtest/gtest.h>

#include <string>

#include "../../md/md_test_util.hpp"
#include "cli_util.hpp"

namespace energy_warning {

std::string run_example(const std::string& name) {
  const auto out = mpmx::test::scratch_root() / ("balance_" + name);
  const auto r = mpmx::test::run_cli(std::string("run ") + MPMX_SOURCE_DIR + "/examples/" + name + ".toml --out " +
                                     out.string() + " --quiet --no-plot");
  EXPECT_EQ(r.status, 0) << r.output;
  return r.output;
}

TEST(EnergyWarning, SaidWhereTheBalanceMissesAndOnlyThere) {
  const std::string bad = run_example("S1_mpm_64ppc");
  EXPECT_NE(bad.find("warning: the kinetic energy's change misses the work of the stresses and the boundaries by"),
            std::string::npos)
      << bad;
  EXPECT_NE(bad.find("conservation.energy.relative_error"), std::string::npos) << bad;
  const std::string good = run_example("A1_standing_wave_moving");
  EXPECT_EQ(good.find("warning"), std::string::npos) << good;
}

}  // namespace energy_warning
