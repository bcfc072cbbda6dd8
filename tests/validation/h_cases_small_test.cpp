// ctest-label: slow
// H1 and H2 on the scaled-down bars (examples/H*_small.toml): direct MD of the bar,
// DDMP with the linear elastic closure, and DDMP-MD, compared by eq. 7.12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "multiscale/ms_test_util.hpp"

namespace {

using namespace mpmx;

// Runs the direct-MD deck with the mpmx binary; returns its bar_stress.csv.
std::string direct_md(const std::string& case_id) {
  const std::string dir = test::scratch_dir(case_id + "_direct");
  const std::string cmd = fmt::format("'{}' md '{}' --out '{}' --quiet > /dev/null", MPMX_BINARY,
                                      test::example(case_id + "_direct_md_small.toml"), dir);
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return dir + "/bar_stress.csv";
}

double error_vs(const std::string& deck, const std::string& reference, const char* precision = nullptr) {
  const auto c = test::deck_with(test::example(deck), [&](toml::table& t) {
    t["reference"].as_table()->insert_or_assign("file", reference);
    if (precision) t["material"]["md"].as_table()->insert_or_assign("precision", precision);
  });
  const auto r = test::run(c);
  return r.stress_vs_direct_md;
}

TEST(H1Small, ThreeMethodsAgree) {
  const std::string ref = direct_md("H1");
  const double md = error_vs("H1_weak_0K_256_small.toml", ref);
  const double elastic = error_vs("H1_ddmp_elastic_small.toml", ref);
  fmt::print("H1 small, eq. 7.12: DDMP-MD {:.4f}, DDMP elastic {:.4f}\n", md, elastic);
  // The weak shock stays near equilibrium: both closures track the direct MD, and each
  // other; what is left is the tanh smoothing of the step against the direct MD's
  // sharp one, large relative to a 0.5% strain on a 40-cell bar (measured 0.215 / 0.214).
  EXPECT_LT(md, 0.25);
  EXPECT_LT(elastic, 0.25);
  EXPECT_LT(std::abs(md - elastic), 0.02);
}

TEST(H2Small, DdmpMdCloserToDirectMdThanElastic) {
  const std::string ref = direct_md("H2");
  const double md = error_vs("H2_strong_0K_256_small.toml", ref);
  const double elastic = error_vs("H2_ddmp_elastic_small.toml", ref);
  const double mixed = error_vs("H2_strong_0K_256_small.toml", ref, "mixed");
  fmt::print("H2 small, eq. 7.12: DDMP-MD {:.4f} (mixed precision {:.4f}), DDMP elastic {:.4f}\n", md, mixed, elastic);
  EXPECT_LT(md, 0.9 * elastic);  // measured 0.123 vs 0.154
  EXPECT_LT(md, 0.16);
  // The boxes in mixed precision (float pairs, double sums): within 0.2 points of double.
  EXPECT_LT(std::abs(mixed - md), 0.002);
}

// H5 (issue 47): the H2 recipe off copper, bcc Ta shocked along [110], 108-atom boxes
// prepared by NPT at 10 K, against the direct MD of the same bar at the prepared lattice
// constant. Measured 0.126 against the elastic closure's 0.173 (C11' of the [110] crystal):
// the bounds are H2 small's, which the copper bar meets at 0.123 against 0.154.
TEST(H5Small, TaAlong110DdmpMdCloserToDirectMdThanElastic) {
  const std::string ref = direct_md("H5_ta_110");
  const double md = error_vs("H5_ta_110_small.toml", ref);
  const double elastic = error_vs("H5_ta_110_ddmp_elastic_small.toml", ref);
  fmt::print("H5 small (Ta [110], NPT at 10 K), eq. 7.12: DDMP-MD {:.4f}, DDMP elastic {:.4f}\n", md, elastic);
  EXPECT_LT(md, 0.9 * elastic);  // measured 0.126 vs 0.173
  EXPECT_LT(md, 0.16);
}

}  // namespace

namespace {

// Standard deviation of the stress of the points ahead of the shock (x > 22 nm) at the
// last step: thermal noise of the 300 K boxes, one box per point (shared boxes would give
// the plateau's points one box, and its noise to all of them alike).
double noise_ahead(const app::RunResult& r) {
  const auto& p = r.state.particles;
  double s = 0, s2 = 0;
  int n = 0;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (p.x[0][q] > 22.0) s += p.stress[0][q], s2 += p.stress[0][q] * p.stress[0][q], ++n;
  const double mean = s / n;
  return std::sqrt(std::max(0.0, s2 / n - mean * mean));
}

TEST(H3Small, NoiseFallsFrom256To500Atoms) {
  auto deck = [](const char* name) {
    return test::deck_with(test::example(name), [](toml::table& t) {
      t.erase("reference");
      t["time"].as_table()->insert_or_assign("end", 1.0);
      t["output"].as_table()->insert_or_assign("times", toml::array{});
      t["material"]["md"].as_table()->insert_or_assign("share", toml::table{{"enabled", false}});
    });
  };
  const double n256 = noise_ahead(test::run(deck("H3_strong_300K_256_small.toml")));
  const double n500 = noise_ahead(test::run(deck("H3_strong_300K_500_small.toml")));
  fmt::print("H3 small, stress noise ahead of the shock: 256 atoms {:.4f} GPa, 500 atoms {:.4f} GPa\n", n256, n500);
  EXPECT_GT(n256, 0.03);        // 300 K boxes are noisy (measured 0.10 GPa) ...
  EXPECT_LT(n500, 0.8 * n256);  // ... and less so with more atoms (measured 0.058)
}

}  // namespace
