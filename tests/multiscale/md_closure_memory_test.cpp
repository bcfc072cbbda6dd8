// ctest-label: slow
// The memory `mpmx check` estimates for a DDMP-MD deck against the peak the run reaches
// (run.json's peak_memory_bytes), on three deck sizes whose MD boxes hold most of it:
// one compact box per point between the macro steps and a whole one per thread while it
// steps. Release builds only (the sanitizers' shadow memory is not the program's).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/app/mpm/budget.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "multiscale/ms_test_util.hpp"

using namespace mpmx;
namespace fs = std::filesystem;

namespace {

// A 1-D bar of `points` unshared boxes of 256 atoms (the deck's cells, more points in
// each), two continuum steps of 10 MD steps.
std::string boxes_deck(int points) {
  std::ifstream in(test::example("H2_strong_0K_256_small.toml"));
  std::stringstream s;
  s << in.rdbuf();
  auto t = toml::parse(s.str());
  const int cells = t["grid"]["cells"].value_or(40);
  t["particles"].as_table()->insert_or_assign("per_cell", points / cells);
  t["time"].as_table()->insert_or_assign("dt", 0.01);  // 10 MD steps
  t["time"].as_table()->insert_or_assign("end", 0.02);
  t["output"].as_table()->insert_or_assign("times", toml::array{});
  t.erase("reference");
  auto& md = *t["material"]["md"].as_table();
  md.insert_or_assign("share", toml::table{{"enabled", false}});
  const fs::path dir = test::scratch_root() / "memory_decks";
  fs::create_directories(dir);
  const fs::path path = dir / fmt::format("bar_{}.toml", points);
  std::ofstream(path) << t;
  return path.string();
}

double peak_of(const std::string& run_json) {
  std::ifstream in(run_json);
  std::string text((std::istreambuf_iterator<char>(in)), {});
  const auto at = text.find("\"peak_memory_bytes\"");
  if (at == std::string::npos) return 0.0;
  return std::stod(text.substr(text.find(':', at) + 1));
}

}  // namespace

TEST(MdClosureMemory, EstimateWithinFifteenPercentOfThePeak) {
  for (int points : {400, 1600, 4800}) {
    const std::string d = boxes_deck(points);
    const auto c = app::read_mpm_deck(d);
    const double estimate = app::estimate_mpm(c).bytes;
    const fs::path out = test::scratch_root() / fmt::format("memory_run_{}", points);
    fs::remove_all(out);
    const std::string cmd =
        fmt::format("'{}' run '{}' --out '{}' --quiet --no-plot --threads 2 >/dev/null 2>&1", MPMX_BINARY, d, out.string());
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const double peak = peak_of((out / "run.json").string());
    ASSERT_GT(peak, 0.0);
    RecordProperty(fmt::format("estimate_over_peak_{}", points), fmt::format("{:.3f}", estimate / peak));
    EXPECT_NEAR(estimate / peak, 1.0, 0.15) << points << " points: estimate " << estimate << ", peak " << peak;
    fs::remove_all(out);
  }
}
