// ctest-label: slow
// H1 and H2 on the scaled-down bars (examples/H*_small.toml): direct MD of the bar,
// DDMP with the linear elastic closure, and DDMP-MD, compared by eq. 7.12.
#include <gtest/gtest.h>

#include <cstdlib>

#include <fmt/format.h>

#include "ms_test_util.hpp"

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

double error_vs(const std::string& deck, const std::string& reference) {
  const auto c = test::deck_with(test::example(deck), [&](toml::table& t) {
    t["reference"].as_table()->insert_or_assign("file", reference);
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
  fmt::print("H2 small, eq. 7.12: DDMP-MD {:.4f}, DDMP elastic {:.4f}\n", md, elastic);
  EXPECT_LT(md, 0.9 * elastic);  // measured 0.123 vs 0.154
  EXPECT_LT(md, 0.16);
}

}  // namespace
