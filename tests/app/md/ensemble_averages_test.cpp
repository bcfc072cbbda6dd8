// run.json's averages of a thermostatted or barostatted run (issue 53, item 6): the mean
// of each thermo column over the window and its standard error from ten block means, read
// back from thermo.csv; and an NPT run of M7's box reports its mean lattice constant, with
// an error, where the last row alone is one sample of a fluctuating box.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "mpmx/app/md/ensemble_averages.hpp"

#include "../../md/md_test_util.hpp"
#include "cli_util.hpp"

namespace ensemble_averages_test {

TEST(EnsembleAverages, BlockMeansAndErrorsOfTheWindow) {
  // 100 rows before the window (T = 1000 K: must not count) and 200 in it, T alternating
  // 299 and 301 K within each block, the block means 290, 292, ..., 308 K.
  std::string csv = "step,time_ps,pe_per_atom_eV,ke_per_atom_eV,etotal_per_atom_eV,temperature_K,sxx_GPa,syy_GPa,"
                    "szz_GPa,sxy_GPa,sxz_GPa,syz_GPa,lx_A,ly_A,lz_A\n";
  for (int k = 0; k < 300; ++k) {
    const bool in = k >= 100;
    const double t = in ? 290.0 + 2.0 * ((k - 100) / 20) + (k % 2 ? 1.0 : -1.0) : 1000.0;
    csv += fmt::format("{},{},-3.5,0.04,-3.46,{},-1,-2,-3,0,0,0,{},20,30\n", 10 * k, 0.01 * k, t, in ? 18.0 : 99.0);
  }
  const auto path = mpmx::test::scratch_file("avg_thermo.csv", csv);
  const toml::table a = mpmx::app::md::ensemble_averages(path.string(), 1000, {0.2, 0.1, 0.05});
  EXPECT_EQ(a["rows"].value_or(0), 200);
  EXPECT_DOUBLE_EQ(a["temperature_K"]["mean"].value_or(0.0), 299.0);
  // Ten block means 290 ... 308 K: their standard deviation sqrt(110 * 4 / 9 * ...) over sqrt(10).
  double var = 0;
  for (int b = 0; b < 10; ++b) var += std::pow(290.0 + 2 * b - 299.0, 2) / 9.0;
  EXPECT_NEAR(a["temperature_K"]["standard_error"].value_or(0.0), std::sqrt(var / 10.0), 1e-12);
  EXPECT_DOUBLE_EQ(a["pressure_GPa"]["mean"].value_or(0.0), 2.0);
  EXPECT_NEAR(a["lattice_constant_x_A"]["mean"].value_or(0.0), 3.6, 1e-12);
  EXPECT_NEAR(a["lattice_constant_z_A"]["mean"].value_or(0.0), 1.5, 1e-12);
  EXPECT_NEAR(a["lattice_constant_x_A"]["standard_error"].value_or(1.0), 0.0, 1e-12);
}

TEST(EnsembleAverages, NptRunReportsItsMeanLatticeConstant) {
  const std::string deck = R"([potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
[lattice]
constant = 3.615
cells = [4, 4, 4]
[thermal]
temperature = 300.0
seed = 3
[run]
dt = 0.002
steps = 2000
thermo = 10
ensemble = "npt"
pressure_gpa = 0.0
)";
  const auto path = mpmx::test::scratch_file("avg_npt.toml", deck);
  const auto out = mpmx::test::scratch_root() / "avg_npt";
  const auto r = mpmx::test::run_cli("md " + path.string() + " --out " + out.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("averages over the run's second half (101 rows"), std::string::npos) << r.output;
  const std::string json = mpmx::test::slurp(out / "run.json");
  // The figures of one entry of "averages": the text after its key.
  auto figure = [&](const std::string& key, const std::string& what) {
    const auto at = json.find("\"averages\"");
    return mpmx::test::json_number(json.substr(json.find("\"" + key + "\"", at)), what);
  };
  const double a = figure("lattice_constant_x_A", "mean");
  const double err = figure("lattice_constant_x_A", "standard_error");
  EXPECT_NEAR(a, 3.632, 0.002);
  EXPECT_GT(err, 0.0);
  EXPECT_LT(err, 0.002);
  EXPECT_NEAR(figure("pressure_GPa", "mean"), 0.0, 0.1);
  EXPECT_NEAR(figure("temperature_K", "mean"), 300.0, 15.0);
}

}  // namespace ensemble_averages_test
