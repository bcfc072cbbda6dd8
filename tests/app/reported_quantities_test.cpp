// Every figure a run reports finite, or the run stops naming the first that is not, its
// step and its time (app/reported_quantities.hpp; issue 45).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "mpmx/app/reported_quantities.hpp"

using mpmx::app::first_non_finite;

TEST(ReportedQuantities, FiniteFiguresPass) {
  EXPECT_EQ(first_non_finite(7, 0.007, "ps", {{"the temperature (K)", 1e29}, {"stress xx (GPa)", -3.0}}), "");
}

TEST(ReportedQuantities, TheFirstNonFiniteIsNamedWithStepAndTime) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const std::string why = first_non_finite(
      40, 0.04, "ps", {{"the potential energy (eV/atom)", -3.5}, {"the kinetic energy (eV/atom)", inf},
                       {"the temperature (K)", nan}});
  EXPECT_NE(why.find("step 40 (t = 0.04 ps): the kinetic energy (eV/atom) is inf: the state went non-finite"),
            std::string::npos)
      << why;
  EXPECT_EQ(why.find("temperature"), std::string::npos) << why;
  EXPECT_NE(first_non_finite(1, 2.5, "ps", {{"the pressure (GPa)", -nan}}).find("the pressure (GPa) is"),
            std::string::npos);
}
