// ctest-label: validation
// ctest-cost: 2000
// Every shipped deck runs, at least its first steps (docs/validation.md, "Every shipped
// deck's first steps", with each deck's cost). Each examples/*.toml but the DPD potential
// files is a test case of its own (read from the folder, so a new deck is picked up), run
// by the command its tables name (run, md, dpd, fit-dpd) at its real size, on one
// thread, stopped by the hidden --stop-after N as by Ctrl-C: the status is 130 with a
// checkpoint at step N (an MD or DPD run stops at its first record at or past N;
// fit-dpd after N finished stages). A deck shorter than N runs whole (status 0). What is
// asserted: the program stopped where asked and not before (no input error, no run
// stopped by the physics), run.json says so ("interrupted", the step), and nothing it
// wrote is non-finite (run.json's non_finite list and the tables' numbers).
//
// What the copy changes: a [reference] that names a file not in the checkout (a direct-MD
// run under ../runs, which `mpmx run` refuses to start without: "reference.file ... is
// not there yet") is dropped, the analytic references and the reference packs under
// ../data stay; file names relative to examples/ are made absolute; the big MD decks
// record sooner (plans()), so that their first record, where md stops, comes after a few
// steps; fit-dpd's isotherm samples fewer steps. run, md and dpd get --force: the
// full-size decks' work estimates are over the day a run takes without it. Each case prints its cost ("[   cost   ]": steps, CPU seconds);
// docs/validation.md has the table.
#include <sys/resource.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "cli_util.hpp"
#include "mpmx/app/deck_kind.hpp"

namespace {

namespace fs = std::filesystem;
using mpmx::app::DeckKind;

const fs::path kExamples = fs::path(MPMX_SOURCE_DIR) / "examples";

// A deck's test: how many steps (stages for fit-dpd), and the keys its copy sets
// (dotted key, value) so that an MD run records at the step it is to stop at.
struct Plan {
  std::int64_t steps;
  std::vector<std::pair<std::string, double>> set{};
};

// Decks whose first steps differ from the default of their kind.
const std::map<std::string, Plan, std::less<>>& plans() {
  static const std::map<std::string, Plan, std::less<>> p = {
      // The continuum study decks (J2-J4 at every scale) take the default 3 steps.
      // The jet's record_every_ps is in ps at scale 1: 2 MD steps of 1 fs.
      {"J1_direct_md_full", {2, {{"jet.record_every_ps", 0.002}}}},
      {"J1_direct_md_s0p05", {2, {{"jet.record_every_ps", 0.04}}}},
      {"J1_direct_md_s0p1", {2, {{"jet.record_every_ps", 0.02}}}},
      {"J1_direct_md_s0p2", {2, {{"jet.record_every_ps", 0.01}}}},
      {"J1_direct_md_s0p5", {2, {{"jet.record_every_ps", 0.004}}}},
      {"J1_direct_md_tiny", {2, {{"jet.record_every_ps", 0.04}}}},
      {"D1_flyer_md_all_atom", {10, {{"run.thermo", 10}}}},  // 1e5 atoms, in its equilibration
      {"H1_direct_md", {10, {{"run.thermo", 10}, {"bar.output_every", 10}}}},
      {"H2_direct_md", {10, {{"run.thermo", 10}, {"bar.output_every", 10}}}},
      {"H3_direct_md", {10, {{"run.thermo", 10}, {"bar.output_every", 10}}}},
  };
  return p;
}

Plan plan_of(const std::string& stem, DeckKind kind) {
  if (auto it = plans().find(stem); it != plans().end()) return it->second;
  switch (kind) {
    // Its first stage is the whole MD isotherm: every density's box at its real size (500
    // atoms), each for 100 + 100 steps instead of 3000 + 5000.
    case DeckKind::fit_dpd: return {1, {{"md.equilibrate_steps", 100}, {"md.sample_steps", 100}}};
    case DeckKind::md: return {1};   // its first record
    case DeckKind::dpd: return {1};  // its first record
    default: return {3};
  }
}

struct Deck {
  std::string stem;
  DeckKind kind;
};

void PrintTo(const Deck& d, std::ostream* os) { *os << d.stem << " (" << mpmx::app::deck_kind_name(d.kind) << ")"; }

std::vector<Deck> shipped_decks() {
  std::vector<Deck> decks;
  for (const auto& e : fs::directory_iterator(kExamples)) {
    if (e.path().extension() != ".toml") continue;
    const DeckKind kind = mpmx::app::deck_kind(e.path().string());
    if (kind == DeckKind::potential) continue;  // what fit-dpd writes, which dpd decks read
    decks.push_back({e.path().stem().string(), kind});
  }
  std::sort(decks.begin(), decks.end(), [](const Deck& a, const Deck& b) { return a.stem < b.stem; });
  return decks;
}

// Sets `dotted` (a.b.c) to `value` in `t`, as an integer where it is one.
void set_key(toml::table& t, const std::string& dotted, double value) {
  toml::table* at = &t;
  std::string rest = dotted;
  for (auto dot = rest.find('.'); dot != std::string::npos; dot = rest.find('.')) {
    at = (*at)[rest.substr(0, dot)].as_table();
    ASSERT_NE(at, nullptr) << dotted;
    rest = rest.substr(dot + 1);
  }
  if (at->get(rest) && at->get(rest)->is_integer())
    at->insert_or_assign(rest, static_cast<std::int64_t>(value));
  else
    at->insert_or_assign(rest, value);
}

// The files a deck reads (its `file` keys: potentials) named beside the deck made
// absolute, so that the copy reads what the deck reads. (fit-dpd's output.potential_file
// is a name in the output folder, left as it is.)
void absolute_paths(toml::node& n) {
  if (auto* t = n.as_table()) {
    for (auto&& [k, v] : *t) {
      auto* s = v.as_string();
      std::error_code ec;
      if (k.str() == "file" && s && fs::path(s->get()).is_relative() && fs::exists(kExamples / s->get(), ec))
        *s = (kExamples / s->get()).lexically_normal().string();
      else
        absolute_paths(v);
    }
  } else if (auto* a = n.as_array()) {
    for (auto& v : *a) absolute_paths(v);
  }
}

// What may be non-finite after the first steps, being not measured yet: the MD jet's
// shock front before it has formed (jet_front.csv's front_x_A; run.json's fits over
// the front's records, shock_speed_km_s and plateau_stress_gpa; docs/guide.md, "jet").
bool not_measured_yet(const std::string& name) {
  return name == "front_x_A" || name == "shock_speed_km_s" || name == "plateau_stress_gpa";
}

std::vector<std::string> split(const std::string& line, char by) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, by);) cells.push_back(c);
  return cells;
}

// The cells of a table (CSV) file that do not parse as a finite number (the header's
// names aside), as "row column: text".
std::string non_finite_cells(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line, bad;
  std::getline(in, line);
  const std::vector<std::string> header = split(line, ',');
  for (int row = 2; std::getline(in, line); ++row) {
    const std::vector<std::string> cells = split(line, ',');
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string name = c < header.size() ? header[c] : std::to_string(c);
      char* end = nullptr;
      const double v = std::strtod(cells[c].c_str(), &end);
      const bool number = end != cells[c].c_str();
      if (number && !std::isfinite(v) && !not_measured_yet(name) && bad.size() < 400)
        bad += fmt::format("{} {}: {}\n", row, name, cells[c]);
    }
  }
  return bad;
}

// The keys run.json lists as non-finite (its "non_finite" array, written as null), less
// those not measured yet.
std::vector<std::string> non_finite_keys(const std::string& json) {
  std::vector<std::string> keys;
  const auto at = json.find("\"non_finite\" : [");
  if (at == std::string::npos) return keys;
  const auto end = json.find(']', at);
  for (auto q = json.find('"', at + 16); q < end; q = json.find('"', q + 1)) {
    const auto close = json.find('"', q + 1);
    const std::string key = json.substr(q + 1, close - q - 1);
    if (!not_measured_yet(key)) keys.push_back(key);
    q = close;
  }
  return keys;
}

// A number at run.json's top level (four spaces in: a nested table, such as a prepared
// NPT box's, may hold the same key first); nan when absent.
double top_level_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\n    \"" + key + "\" : ");
  return at == std::string::npos ? std::nan("") : mpmx::test::json_number(json.substr(at), key);
}

// The CPU time (user + system) of the finished child processes so far.
double children_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_CHILDREN, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

class ShippedDeck : public ::testing::TestWithParam<Deck> {};

TEST_P(ShippedDeck, RunsItsFirstSteps) {
  const Deck& d = GetParam();
  const Plan plan = plan_of(d.stem, d.kind);
  const fs::path dir = fs::path(::testing::TempDir()) / "mpmx_shipped_decks" / d.stem;
  fs::remove_all(dir);
  fs::create_directories(dir);

  toml::table t = toml::parse_file((kExamples / (d.stem + ".toml")).string());
  if (auto* ref = t["reference"].as_table(); ref && ref->contains("file")) {
    std::error_code ec;
    const auto* f = ref->get_as<std::string>("file");
    if (!f || !fs::exists(kExamples / f->get(), ec)) t.erase("reference");
  }
  absolute_paths(t);
  for (const auto& [key, value] : plan.set) {
    set_key(t, key, value);
    if (HasFatalFailure()) return;
  }
  const fs::path deck = dir / (d.stem + ".toml"), out = dir / "out";
  std::ofstream(deck) << t << '\n';

  const std::string args =
      fmt::format("{} '{}' --out '{}' --threads 1 --quiet --no-plot --stop-after {}{}", mpmx::app::deck_command(d.kind),
                  deck.string(), out.string(), plan.steps, d.kind == DeckKind::fit_dpd ? "" : " --force");
  const double cpu0 = children_cpu_seconds();
  const auto r = mpmx::test::run_cli(args);
  const double cpu = children_cpu_seconds() - cpu0;
  // "interrupted: step S of ...": S is N, or for md and dpd the first record at or past N;
  // a convergence study (which does not resume) says "..., at step S; it does not resume".
  const auto at = r.output.find("interrupted: step "), level_at = r.output.find(", at step ");
  const long long step = at != std::string::npos         ? std::atoll(r.output.c_str() + at + 18)
                         : level_at != std::string::npos ? std::atoll(r.output.c_str() + level_at + 10)
                                                         : -1;
  // A convergence study (N4) runs its levels in out/level_K; a stop ends it in the first.
  const fs::path run = fs::exists(out / "run.json") ? out : out / "level_0";
  const std::string json = mpmx::test::slurp(run / "run.json");
  // The cost, for docs/validation.md's table (printed, never asserted): the steps run
  // (fit-dpd: the stages), the CPU seconds of the program.
  const long long reached = d.kind == DeckKind::fit_dpd ? static_cast<long long>(plan.steps)
                            : step >= 0 ? step
                                        : std::llround(top_level_number(json, "steps"));
  std::printf("[   cost   ] %s: %s %lld, %.2f s of CPU\n", d.stem.c_str(),
              d.kind == DeckKind::fit_dpd ? "stages" : "steps", reached, cpu);
  // Stopped where asked (130, a checkpoint), or a deck no longer than that run whole (M1).
  ASSERT_TRUE(r.status == 130 || r.status == 0) << "mpmx " << args << "\n" << r.output;
  EXPECT_EQ(r.output.find("run stopped"), std::string::npos) << r.output;
  if (r.status == 130) {
    EXPECT_NE(json.find("\"status\" : \"interrupted\""), std::string::npos) << json.substr(0, 2000);
    EXPECT_TRUE(fs::exists(run / "checkpoint.bin"));
    if (d.kind == DeckKind::continuum) {
      EXPECT_EQ(step, plan.steps) << r.output;
      EXPECT_EQ(top_level_number(json, "steps"), static_cast<double>(plan.steps));
    } else if (d.kind != DeckKind::fit_dpd) {
      EXPECT_GE(step, plan.steps) << r.output;
    }
  } else {
    EXPECT_NE(json.find("\"status\" : \"completed\""), std::string::npos) << json.substr(0, 2000);
  }
  // Nothing non-finite: run.json lists such numbers under non_finite (written as null).
  EXPECT_EQ(non_finite_keys(json), std::vector<std::string>{}) << json.substr(0, 4000);
  for (const auto& e : fs::recursive_directory_iterator(out)) {
    // The x-t diagram's cells without material are NaN by design (docs/guide.md, output.xt).
    if (e.path().extension() != ".csv" || e.path().filename().string().starts_with("xt_")) continue;
    EXPECT_EQ(non_finite_cells(e.path()), "") << e.path();
  }
  if (!HasFailure()) fs::remove_all(dir);  // a full-size deck's checkpoint is large
}

std::string case_name(const ::testing::TestParamInfo<Deck>& info) {
  std::string name = info.param.stem;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Examples, ShippedDeck, ::testing::ValuesIn(shipped_decks()), case_name);

// The list holds every kind, so that a folder the test cannot read fails here, not as
// an empty list of cases.
TEST(ShippedDecks, TheListHoldsEveryKind) {
  std::map<DeckKind, int> n;
  for (const Deck& d : shipped_decks()) ++n[d.kind];
  EXPECT_GE(n[DeckKind::continuum], 100);
  EXPECT_GE(n[DeckKind::md], 10);
  EXPECT_GE(n[DeckKind::dpd], 10);
  EXPECT_GE(n[DeckKind::fit_dpd], 1);
}

}  // namespace
