// The memory and work estimates of MD decks (issue 17, app/md/budget.hpp): a lattice the
// machine cannot hold is refused even when forced, work above a day unless forced, and
// the estimate is close to the measured peak memory.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "mpmx/app/md/budget.hpp"
#include "mpmx/app/md/config.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/io/deck.hpp"
#include "md_deck_util.hpp"

using namespace mpmx::md;
using namespace mpmx::app::md;

namespace {

using mpmx::test::lj_deck;
using mpmx::test::md_config_of;

std::string budget_error(const MdBudget& b, std::uint64_t memory, bool force) {
  try {
    check_md_budget(b, memory, force);
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MdBudget, AThousandCubedLatticeIsRefusedForMemoryEvenWhenForced) {
  const auto c = md_config_of(lj_deck("1000, 1000, 1000", "10"));
  const auto b = estimate_md(c, 5.0);
  EXPECT_EQ(b.atoms, 4e9);
  EXPECT_GT(b.bytes, 4e9 * 300);
  const std::uint64_t memory = 64ull << 30;
  const auto msg = budget_error(b, memory, /*force=*/true);
  EXPECT_NE(msg.find("lattice.cells: 4e+09 atoms need about"), std::string::npos) << msg;
  EXPECT_NE(msg.find("more than this machine's 64 GiB"), std::string::npos) << msg;
}

TEST(MdBudget, WorkAboveADayIsRefusedUnlessForced) {
  // 500 atoms x 1e9 steps = 5e11 atom-steps.
  const auto c = md_config_of(lj_deck("5", "1000000000"));
  const auto b = estimate_md(c, 5.0);
  EXPECT_EQ(b.atom_steps, 5e11);
  const auto msg = budget_error(b, 64ull << 30, false);
  EXPECT_NE(msg.find("run.steps: 500 atoms x 1e+09 steps = 5e+11 atom-steps"), std::string::npos) << msg;
  EXPECT_NE(msg.find("without --force"), std::string::npos) << msg;
  EXPECT_EQ(budget_error(b, 64ull << 30, true), "");
  // The largest int64 step count: the product is figured in floating point, no overflow.
  const auto c2 = md_config_of(lj_deck("5", "9223372036854775807"));
  EXPECT_NE(budget_error(estimate_md(c2, 5.0), 64ull << 30, false).find("run.steps: 500 atoms x 9.223e+18"),
            std::string::npos);
}

TEST(MdBudget, EstimateIsCloseToMeasuredPeakMemory) {
  // Peak RSS measured with `mpmx md --threads 2` on Cu EAM (cutoff 5.507): 32,000 atoms
  // 86.7 MB, 131,072 atoms 303 MB, 340,736 atoms 743 MB (the constants in budget.cpp were
  // fitted to these).
  auto c = md_config_of(lj_deck("20", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 86.7e6, 1.0, 0.15);
  c = md_config_of(lj_deck("32", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 303e6, 1.0, 0.15);
  c = md_config_of(lj_deck("44", "20"));
  EXPECT_NEAR(estimate_md(c, 5.50679).bytes / 743e6, 1.0, 0.15);
}

// Issue 31: a jet's bins beyond its atoms (1e6 bins for 350 atoms wrote 859 MB) are refused,
// naming jet.bins and what the tables would take; the study's bins pass.
TEST(MdBudget, JetBinsBeyondTheAtomsAreRefused) {
  // One literal: GCC 12 warns (-Warray-bounds) of operator+ on a temporary here, wrongly.
  std::ifstream in(MPMX_SOURCE_DIR "/examples/J1_direct_md_s0p1.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const auto good = estimate_md(md_config_of(text), 5.0);
  EXPECT_EQ(good.bins, 800);
  EXPECT_NEAR(good.output_bytes, 230.0 * 800 * 31, 1.0);  // 31 records
  EXPECT_EQ(budget_error(good, 0, false), "");
  text.replace(text.find("bins = [40, 20]"), 15, "bins = [100000, 100]");
  const std::string e = budget_error(estimate_md(md_config_of(text), 5.0), 0, false);
  EXPECT_NE(e.find("jet.bins: 1e+07 bins for 2.802e+04 atoms"), std::string::npos) << e;
}

// A box a few angstrom across under a cutoff of hundreds: the ghost layer would span more
// periodic images than the neighbour list tracks, which the run found only at its start
// (exit 3, nothing written); now the estimate refuses it with the figure (issue 45).
TEST(MdBudget, ACutoffAcrossTooManyBoxLengthsIsRefused) {
  auto c = md_config_of(lj_deck("1", "10"));
  auto msg = budget_error(estimate_md(c, 500.0), 0, false);
  EXPECT_NE(msg.find("lattice.cells: the potential's cutoff plus run.skin reaches 138.6 times across the box's "
                     "shortest edge: at most 100 periodic images"),
            std::string::npos)
      << msg;
  EXPECT_EQ(budget_error(estimate_md(c, 5.0), 0, false), "");
}
