// The direct-MD jet's reference packs kept in git (data/J1_direct_md_SCALE, made by
// scripts/jet-reference-pack; docs/jet.md, "Reference packs"): each reads as a jet
// history with records at its scale's compared times, and the s = 0.1 pack gives the
// coarse row's eq. 7.12 to the digits the row's run reported against the whole run:
// the points of examples/J3_ddmp_md_50x25_1ppc_s0p1.toml at the scaled 10 and 20 ps
// (data/J3_ddmp_md_50x25_1ppc_s0p1_points.csv) against the pack's bins.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "mpmx/reference/bar_history.hpp"
#include "mpmx/reference/jet_history.hpp"

namespace fs = std::filesystem;
using namespace mpmx;

namespace {

const fs::path kData = fs::path(MPMX_SOURCE_DIR) / "data";

}  // namespace

TEST(JetReferencePack, TheCoarseRowsEq712FromTheCommittedBins) {
  const auto jet = reference::JetHistory::read((kData / "J1_direct_md_s0p1").string());
  std::ifstream in(kData / "J3_ddmp_md_50x25_1ppc_s0p1_points.csv");
  ASSERT_TRUE(in) << "data/J3_ddmp_md_50x25_1ppc_s0p1_points.csv";
  std::string line;
  std::getline(in, line);
  ASSERT_EQ(line, "time_ps,x_nm,y_nm,sxx_GPa");
  std::map<double, reference::Eq712> by_time;
  std::map<double, int> compared;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    double v[4];
    char comma = 0;
    ss >> v[0] >> comma >> v[1] >> comma >> v[2] >> comma >> v[3];
    ASSERT_TRUE(ss) << line;
    // The continuum's x = 0 is the piston's face; nm to Angstrom.
    const double md = jet.sxx(v[0], jet.piston_face_A() + 10.0 * v[1], 10.0 * v[2]);
    if (!std::isfinite(md)) continue;
    by_time[v[0]].add(v[3], md);
    ++compared[v[0]];
  }
  ASSERT_EQ(by_time.size(), 2u);
  // The row's run.json against the whole direct-MD run: 30.23817147% and 24.85046899%
  // over 977 and 963 points (tools/check_eq712.py agrees to 2e-15).
  EXPECT_EQ(compared[1.0], 977);
  EXPECT_EQ(compared[2.0], 963);
  EXPECT_NEAR(100 * by_time[1.0].value(), 30.23817147, 1e-8);
  EXPECT_NEAR(100 * by_time[2.0].value(), 24.85046899, 1e-8);
}

TEST(JetReferencePack, EachScaleHasItsComparedTimes) {
  // The scaled 10 and 20 ps of Table 7.1 at each kept scale (s = 0.1 also the J2 row's 30).
  for (const auto& [name, s] : std::map<std::string, double>{
           {"J1_direct_md_s0p05", 0.05}, {"J1_direct_md_s0p1", 0.1}, {"J1_direct_md_s0p2", 0.2},
           {"J1_direct_md_s0p5", 0.5}}) {
    SCOPED_TRACE(name);
    const auto jet = reference::JetHistory::read((kData / name).string());
    EXPECT_TRUE(jet.has(10 * s));
    EXPECT_TRUE(jet.has(20 * s));
    // The shocked copper behind the front at the scaled 10 ps: sigma_xx near J1's 172 GPa
    // plateau halfway from the face to the front (5.21 km/s from the face: 521 s Angstrom
    // at the scaled 10 ps), at a quarter of the period (723 s Angstrom).
    const double x = jet.piston_face_A() + 0.5 * 521.0 * s, y = 0.25 * 723.0 * s;
    EXPECT_NEAR(jet.sxx(10 * s, x, y), -172.0, 25.0);
  }
}
