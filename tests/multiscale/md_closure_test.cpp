// md_closure: the MD box of every material point (section 6.2), thread-count
// independence, checkpoint/resume, conservation, deck checks.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "mpmx/app/md/config.hpp"
#include "mpmx/md/potential/registry.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/mpm/points.hpp"
#include "ms_test_util.hpp"

namespace {

using namespace mpmx;

void expect_same_particles(const mpm::Particles<1>& a, const mpm::Particles<1>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t q = 0; q < a.size(); ++q) {
    ASSERT_EQ(a.x[0][q], b.x[0][q]) << q;
    ASSERT_EQ(a.v[0][q], b.v[0][q]) << q;
    ASSERT_EQ(a.stress[0][q], b.stress[0][q]) << q;
    ASSERT_EQ(a.volume[q], b.volume[q]) << q;
  }
}

TEST(Equilibrium, CopperLatticeAndModulus) {
  const auto eq = md::fcc_equilibrium(test::copper());
  EXPECT_NEAR(eq.lattice_constant, 3.61493, 1e-5);    // M1
  EXPECT_NEAR(eq.energy_per_atom, -3.54022, 1e-5);
  EXPECT_NEAR(eq.c11_gpa, 169.9, 0.02 * 169.9);        // M4 target
}

TEST(MdClosure, UnstrainedPointAtZeroKelvinHasZeroStress) {
  auto c = test::tiny_bar(4, 3, 2);
  auto md_cfg = test::closure_config(c);
  md_cfg.threads = 1;
  multiscale::MdClosure<1> m(md_cfg);
  mpm::Particles<1> p = test::two_points(-0.01);
  m.initialize(mpm::points(p));
  EXPECT_LT(std::abs(p.stress[0][0]), 1e-9);  // GPa; round-off of a 108-atom virial sum
  // Compressed: about C11 e, stiffer in compression.
  EXPECT_LT(p.stress[0][1], -1.0 * 169.9 * 0.01);
  EXPECT_GT(p.stress[0][1], -1.1 * 169.9 * 0.01);
  // At rest and zero strain rate it stays so: 100 MD steps per continuum step.
  p.grad_v[0] = {0.0, 0.0};
  m.update_stress(mpm::points(p), 0.1);
  EXPECT_LT(std::abs(p.stress[0][0]), 1e-9);
  EXPECT_EQ(m.atom_steps(), 2 * 108 * 100);
  // Units in one place: a gradient of 1/ps stretches the box like exp(t).
  p.grad_v[0] = {0.05, 0.0};
  m.update_stress(mpm::points(p), 0.1);
  EXPECT_NEAR(p.strain[0][0], std::expm1(0.005), 1e-6);
  EXPECT_GT(p.stress[0][0], 0.0);
}

TEST(MdClosure, SameResultOnOneAndTwoThreads) {
  const auto c = test::tiny_bar(8, 2, 4, 300.0);
  app::RunOptions o;
  o.quiet = true;
  o.threads = 1;
  const auto one = app::run_mpm(c, o);
  o.threads = 2;
  const auto two = app::run_mpm(c, o);
  EXPECT_EQ(one.threads, 1);
  EXPECT_EQ(two.threads, 2);
  expect_same_particles(one.state.particles, two.state.particles);
  EXPECT_GT(one.md_atom_steps, 8 * 32 * 400);
}

TEST(MdClosure, ResumedRunEqualsUninterruptedRun) {
  const auto c = test::tiny_bar(6, 2, 6, 300.0);
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("whole");
  const auto whole = app::run_mpm(c, o);
  o.out_dir = test::scratch_dir("parts");
  o.stop_after = 2;
  const auto first = app::run_mpm(c, o);
  EXPECT_TRUE(first.interrupted);
  EXPECT_EQ(first.steps, 2);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm(c, o);
  EXPECT_FALSE(rest.interrupted);
  EXPECT_EQ(rest.steps, 6);
  expect_same_particles(whole.state.particles, rest.state.particles);
  EXPECT_EQ(whole.md_atom_steps, rest.md_atom_steps);
  EXPECT_FALSE(std::filesystem::exists(app::checkpoint_path(o.out_dir)));  // removed once complete
  // A changed deck does not resume.
  o.out_dir = test::scratch_dir("changed");
  o.resume = false;
  o.stop_after = 1;
  app::run_mpm(c, o);
  auto other = c;
  other.deck.insert_or_assign("extra", 1);
  o.resume = true;
  o.stop_after = 0;
  EXPECT_THROW(app::run_mpm(other, o), InputError);
}

TEST(MdClosure, ResumedTablesEqualUninterruptedTables) {
  auto c = test::tiny_bar(6, 2, 6);
  c.output_every = 1;
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  const std::string whole = test::scratch_dir("tables_whole"), parts = test::scratch_dir("tables_parts");
  o.out_dir = whole;
  app::run_mpm(c, o);
  o.out_dir = parts;
  o.stop_after = 3;
  app::run_mpm(c, o);
  o.stop_after = 0;
  o.resume = true;
  app::run_mpm(c, o);
  for (const char* f : {"particles.csv", "nodes.csv", "energy.csv"}) {
    const std::string a = test::read_file(whole + "/" + f), b = test::read_file(parts + "/" + f);
    EXPECT_FALSE(a.empty()) << f;
    EXPECT_EQ(a, b) << f;
  }
}

TEST(MdClosure, MomentumBalancesTheBoundaryImpulse) {
  const auto c = test::tiny_bar(10, 2, 5);
  app::RunOptions o;
  o.quiet = true;
  const auto r = app::run_mpm(c, o);
  EXPECT_GT(std::abs(r.boundary_impulse), 0.0);  // the compressed end pushes on its wall
  EXPECT_LT(r.momentum_error(), 1e-12 * r.momentum_scale + 1e-14);
}

// The H2 small deck edited by `edit` must be refused with `text` in the message.
template <class Edit>
void expect_deck_error(Edit edit, const std::string& text) {
  try {
    test::deck_with(test::example("H2_strong_0K_256_small.toml"), edit);
    ADD_FAILURE() << "accepted; expected an error naming '" << text << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

// A direct-MD table without a record at a compared time is refused before the run,
// not skipped; the times it has are compared by eq. 7.12 and the units recorded.
TEST(DirectMdReference, ComparedTimesMustBeInTheTable) {
  const std::string dir = test::scratch_dir("direct_md_table");
  {
    std::ofstream f(dir + "/bar_stress.csv");
    f << "step,time_ps,bin,x_A,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,sxz_GPa,syz_GPa\n";
    for (int step : {0, 100, 200})
      for (int b = 0; b < 4; ++b) f << fmt::format("{},{},{},0,{},0,0,0,0,0\n", step, step * 0.001, b, b < 2 ? -9.0 : 0.0);
  }
  auto with_times = [&](toml::array times) {
    auto c = test::tiny_bar(8, 2, 3);
    c.reference.name = "direct_md";
    c.reference.file = dir + "/bar_stress.csv";
    c.reference.fields = {"stress"};
    c.reference.times.clear();
    for (const auto& t : times) c.reference.times.push_back(t.value_or(0.0));
    return c;
  };
  try {
    test::run(with_times(toml::array{0.1, 0.3}));
    ADD_FAILURE() << "a compared time beyond the table was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no record at t = 0.3"), std::string::npos) << e.what();
  }
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("direct_md_run");
  const auto r = app::run_mpm(with_times(toml::array{0.1, 0.2}), o);
  EXPECT_GT(r.stress_vs_direct_md, 0.0);
  EXPECT_LT(r.stress_vs_direct_md, 1.0);
  const std::string json = test::read_file(o.out_dir + "/run.json");
  EXPECT_NE(json.find("\"stress_vs_direct_md\""), std::string::npos);
  EXPECT_NE(json.find("\"time_ps\""), std::string::npos);  // units for tools/plot
}

TEST(MdClosureDeck, ErrorsNameTheKey) {
  expect_deck_error([](toml::table& t) { t["case"].as_table()->insert_or_assign("units", "furlongs"); },
                    "case.units");
  expect_deck_error([](toml::table& t) { t["time"].as_table()->insert_or_assign("dt", 0.0995); },
                    "whole number of MD steps");
  expect_deck_error([](toml::table& t) { t["material"].as_table()->insert_or_assign("density", 8.9); },
                    "material.density");
}

}  // namespace

namespace {

// Every H deck is valid, and each continuum deck describes the bar of the direct-MD
// deck it compares with: the same strain, and a grid spanning the strained bar.
TEST(HDecks, ValidAndDescribeTheirDirectMdBar) {
  namespace fs = std::filesystem;
  const auto cu = multiscale::md_closure_properties(test::copper_spec(), *units::unit_system("nm_ps_GPa"));
  const double a0 = cu.equilibrium.lattice_constant;
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(MPMX_SOURCE_DIR) / "examples")) {
    const std::string name = e.path().filename().string();
    if (name[0] != 'H' || name.find("direct_md") != std::string::npos) continue;
    const auto c = app::read_mpm_deck(e.path().string());
    ASSERT_EQ(c.reference.name, "direct_md") << name;
    const std::string md_deck = fs::path(c.reference.file).parent_path().filename().string() + ".toml";
    auto deck = io::Deck::from_file((fs::path(MPMX_SOURCE_DIR) / "examples" / md_deck).string());
    const auto md = app::md::read_md_config(deck);
    ASSERT_TRUE(md.bar) << md_deck;
    const auto& b = md.bar_config;
    EXPECT_EQ(c.strain.left, b.strain_left) << name;
    // x's periodic length: a for fcc along the axes, sqrt(2) a for bcc along [110] (H5).
    const double tile = particles::lattice_tile(b.lattice).length[0];
    const double length_nm = 0.1 * b.cells_x * tile * (1 + 0.5 * b.strain_left);
    EXPECT_NEAR(c.upper - c.lower, length_nm, 1e-6 * length_nm) << name;
    EXPECT_NEAR(c.strain.at, 0.5 * 0.1 * b.cells_x * tile * (1 + b.strain_left), 1e-6) << name;
    // The direct MD's crystal at its potential's least-energy constant: the 0 K one for
    // fcc along the axes (the seed's decks); another crystal's warm bar within its thermal
    // expansion of it (H5: NPT's at 10 K, the closure's prepared boxes').
    const auto crystal = multiscale::md_closure_properties(md.potential, *units::unit_system("nm_ps_GPa"), b.lattice);
    const double a = crystal.equilibrium.lattice_constant;
    if (c.material.model == "md_closure") {  // the closure's crystal is the direct MD's
      const auto md_cfg = test::closure_config(c);
      EXPECT_EQ(md_cfg.lattice.style, b.lattice.style) << name;
      EXPECT_EQ(md_cfg.lattice.orient, b.lattice.orient) << name;
      if (md_cfg.prepare == multiscale::BoxPrepare::npt) {
        EXPECT_EQ(md_cfg.temperature, md.temperature) << name;
      }
    }
    if (b.lattice.plain_fcc()) {
      EXPECT_NEAR(a, a0, 1e-12) << md_deck;
    }
    const bool warm = !b.lattice.plain_fcc() && md.temperature > 0;
    EXPECT_NEAR(b.lattice_constant, a, (warm ? 1e-3 : 1e-9) * a) << md_deck;
    if (c.material.model == "linear_elastic") {  // the companion: the MD crystal's C11 and density
      EXPECT_NEAR(c.material.youngs_modulus, crystal.modulus, 1e-5 * crystal.modulus) << name;
      EXPECT_NEAR(c.material.density, crystal.density, 1e-5 * crystal.density) << name;
      EXPECT_TRUE(c.material.density_unstrained) << name;
    }
    ++n;
  }
  EXPECT_GE(n, 20);
}

}  // namespace
