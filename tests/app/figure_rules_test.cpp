// ctest-label: unit
// The colour rule of every map mpmx draws (tools/plot/colour_scale.py, issue 46 item 8): a
// field of both signs in a diverging map centred on zero with symmetric limits from the
// 1st and 99th percentiles, one of one sign in viridis, and a caption that says how many
// values lie beyond the limits and their extremes. And a quasi-1-D 2-D run's figure
// carries the sigma_xx(x) profile beside its maps.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "mpm/mpm_test_util.hpp"

// Helpers and tests in a namespace of their own: the unit tests build in unity batches.
namespace figure_rules {

using namespace mpmx;
namespace fs = std::filesystem;

bool have_matplotlib() {
  return std::system(MPMX_PYTHON " -c 'import matplotlib, numpy' >/dev/null 2>&1") == 0;
}

// colour_scale.Scale of `values` (a Python list expression): "lo hi cmap below above",
// then the caption on its own line.
std::string scale_of(const std::string& values) {
  const std::string cmd = std::string(MPMX_PYTHON) + " -c \"import sys; sys.path.insert(0, '" + MPMX_SOURCE_DIR +
                          "/tools/plot'); from colour_scale import Scale; s = Scale(" + values +
                          "); print(repr(s.lo), repr(s.hi), s.cmap, s.below, s.above); print(s.caption('GPa'))\"";
  return test::capture(cmd);
}


TEST(ColourScale, SignedFieldsAreDivergingAboutZeroWithPercentileLimitsAndTheClippedSaid) {
  if (!have_matplotlib()) GTEST_SKIP() << "python3-numpy is not installed";
  // -100..50 and one contact point at -1000, 152 values: the 1st percentile lies 0.51 of
  // the way from -100 to -99 (-99.49), the 99th at 48.49; symmetric about zero the limits
  // are +-99.49, the contact point and -100 below.
  std::istringstream in(scale_of("list(range(-100, 51)) + [-1000]"));
  double lo = 0, hi = 0;
  std::string cmap;
  int below = -1, above = -1;
  in >> lo >> hi >> cmap >> below >> above;
  ASSERT_TRUE(in) << in.str();
  EXPECT_EQ(cmap, "RdBu_r");
  EXPECT_EQ(lo, -hi);
  EXPECT_NEAR(hi, 99.49, 1e-9);
  EXPECT_EQ(below, 2);  // -1000 and -100
  EXPECT_EQ(above, 0);
  std::string caption;
  std::getline(in, caption);
  std::getline(in, caption);
  EXPECT_NE(caption.find("1st-99th percentile, symmetric about 0"), std::string::npos) << caption;
  EXPECT_NE(caption.find("2 below (down to -1e+03 GPa)"), std::string::npos) << caption;

  // One sign (a density): viridis, the percentiles themselves, nothing centred.
  std::istringstream pos(scale_of("[8.9 + 0.01 * k for k in range(201)]"));
  pos >> lo >> hi >> cmap >> below >> above;
  ASSERT_TRUE(pos) << pos.str();
  EXPECT_EQ(cmap, "viridis");
  EXPECT_NEAR(lo, 8.92, 1e-9);
  EXPECT_NEAR(hi, 10.88, 1e-9);
  EXPECT_EQ(below, 2);
  EXPECT_EQ(above, 2);
}

// N6 shortened: its stress_xx.png stacks the maps over the sigma_xx(x) profile, 2.6 inches
// (390 pixels at 150 dpi) taller than the same maps drawn with --no-profile.
TEST(Figures, AQuasi1dRunDrawsItsProfileBesideTheMaps) {
  if (!have_matplotlib() || std::system(MPMX_PYTHON " -c 'import vtk' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-matplotlib or python3-vtk9 is not installed";
  const fs::path dir = fs::temp_directory_path() / ("mpmx_figures_test_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const auto c = test::deck_with(test::example("N6_copper_planar_impact.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.05);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
  });
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  app::run_mpm_dim<2>(c, o);  // plots as `mpmx run` does
  ASSERT_TRUE(fs::exists(dir / "stress_xx.png"));
  const std::string script = std::string(MPMX_PYTHON) + " '" + MPMX_SOURCE_DIR + "/tools/plot/points2d.py' ";
  const std::string maps = (dir / "maps.png").string();
  ASSERT_NE(test::capture(script + "'" + (dir / "particles.pvd").string() +
                          "' --field stress --component xx --frames 4 --no-profile --out '" + maps + "'"),
            "");
  // PNG height: bytes 20-23 of the IHDR chunk, big-endian.
  auto height = [](const fs::path& png) {
    const std::string b = test::slurp(png.string());
    return b.size() < 24 ? 0u
                         : (unsigned(static_cast<unsigned char>(b[20])) << 24) |
                               (unsigned(static_cast<unsigned char>(b[21])) << 16) |
                               (unsigned(static_cast<unsigned char>(b[22])) << 8) | static_cast<unsigned char>(b[23]);
  };
  const unsigned with = height(dir / "stress_xx.png"), without = height(maps);
  EXPECT_GT(without, 0u);
  EXPECT_NEAR(static_cast<double>(with) - without, 390.0, 40.0) << with << " " << without;
  fs::remove_all(dir);
}

}  // namespace figure_rules
