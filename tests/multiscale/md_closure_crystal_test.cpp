// md_closure's crystals and the NPT preparation (issue 47): [material.md] lattice,
// orient, c_over_a and cells as tiles, the constants from lattice_equilibrium, and
// prepare = "npt" setting every box's lattice constant, in run.json, the checkpoint and
// `mpmx check`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/app/mpm/prepare.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "mpmx/mpm/points.hpp"
#include "ms_test_util.hpp"

namespace {

using namespace mpmx;

// The H5 bar (bcc Ta, x along [110], 108-atom boxes) cut to `points` points and `steps`
// steps of 0.1 ps, without its reference; `prepare_steps` for its NPT preparation.
app::MpmConfig ta_bar(int points, int steps, std::int64_t prepare_steps = 2000) {
  return test::deck_with(test::example("H5_ta_110_small.toml"), [&](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", points);
    t["material"]["md"].as_table()->insert_or_assign("prepare_steps", prepare_steps);
    t["material"]["md"].as_table()->insert_or_assign("relax_steps", 20);
    t["initial"]["strain"].as_table()->insert_or_assign("cells", 2.0);
    t["time"].as_table()->insert_or_assign("end", 0.1 * steps);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
    t.erase("reference");
  });
}

double figure(const app::RunResult& r, const std::string& key) {
  const auto v = test::closure_figure(r, key);
  return std::holds_alternative<double>(v) ? std::get<double>(v) : static_cast<double>(std::get<std::int64_t>(v));
}

// The deck's crystal is read as an md deck's [lattice]; its constants are the oriented
// crystal's (lattice_equilibrium), and a box is cells^3 tiles of it, x along [110].
TEST(MdClosureCrystal, BccAlong110BuildsOrientedBoxesAtTheCrystalsConstants) {
  auto md = test::closure_config(ta_bar(2, 1));
  EXPECT_EQ(md.lattice.style, particles::LatticeStyle::bcc);
  const particles::Orient o110 = {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};
  EXPECT_EQ(md.lattice.orient, o110);
  EXPECT_EQ(md.prepare, multiscale::BoxPrepare::npt);
  EXPECT_EQ(md.atoms_per_point(), 108);  // 3^3 tiles of sqrt(2) a x sqrt(2) a x a, 4 atoms each
  const md::Potential pot(md.potential);
  const auto eq = md::lattice_equilibrium(pot, md.lattice);
  const auto props = multiscale::md_closure_properties(md.potential, md.units, md.lattice);
  EXPECT_EQ(props.equilibrium.lattice_constant, eq.lattice_constant);
  EXPECT_EQ(props.equilibrium.c11_gpa, eq.c11_gpa);
  EXPECT_NEAR(eq.lattice_constant, 3.302531, 1e-6);  // Ta of Zhou's Cu-Ta EAM
  // bcc along [110]: C11' = (C11 + C12 + 2 C44) / 2 of the cube axes, about 293 GPa.
  EXPECT_NEAR(props.equilibrium.c11_gpa, 292.85, 0.05);

  md.prepare = multiscale::BoxPrepare::lattice;  // the 0 K placement: the box at a0
  md.temperature = 0.0;
  md.relax_steps = 0;
  md.threads = 1;
  multiscale::MdClosure<1> m(md);
  mpm::Particles<1> p = test::two_points(-0.01);
  m.initialize(mpm::points(p));
  const double a = eq.lattice_constant;
  const auto& box0 = m.box(0)->box();
  EXPECT_NEAR(box0.lx, 3 * std::sqrt(2.0) * a, 1e-12);
  EXPECT_NEAR(box0.ly, 3 * std::sqrt(2.0) * a, 1e-12);
  EXPECT_NEAR(box0.lz, 3 * a, 1e-12);
  EXPECT_EQ(m.box(0)->atoms().size(), 108u);
  EXPECT_LT(std::abs(p.stress[0][0]), 1e-3);  // GPa: the least-energy lattice, unstressed
  EXPECT_LT(p.stress[0][1], -0.95 * eq.c11_gpa * 0.01);  // compressed by 1%: about C11' e
  EXPECT_GT(p.stress[0][1], -1.1 * eq.c11_gpa * 0.01);
  EXPECT_EQ(m.box_lattice_constant(), a);
}

// prepare = "npt": one box relaxed at (10 K, 0 GPa) sets the lattice constant every
// point's box is built at; run.json holds it beside the 0 K one, the same on any thread
// count and after a resume.
TEST(MdClosureCrystal, NptPreparationSetsEveryBoxsLatticeConstant) {
  const auto c = ta_bar(6, 3);
  const auto md = test::closure_config(c);
  const md::Potential pot(md.potential);
  const double a0 = md::lattice_equilibrium(pot, md.lattice).lattice_constant;
  const auto prep = multiscale::prepare_npt(pot, md, a0);
  EXPECT_GT(prep.lattice_constant, a0);               // thermal expansion at 10 K: small, positive
  EXPECT_LT(prep.lattice_constant, a0 * (1 + 2e-4));
  EXPECT_LT(std::abs(prep.pressure_gpa), 0.05);       // its mean pressure about zero
  EXPECT_NEAR(prep.temperature, 10.0, 2.0);
  EXPECT_EQ(multiscale::prepare_npt(pot, md, a0).lattice_constant, prep.lattice_constant);  // deterministic
  // The deck's reading leaves the box to the run (check states it); prepared for the run,
  // the law holds the same box's result and the points carry its crystal's density.
  EXPECT_FALSE(md.prepared);
  const double rho0 = multiscale::md_closure_properties(md.potential, md.units, md.lattice).density;
  EXPECT_EQ(c.material.density, rho0);
  const app::MpmConfig ready = app::prepared_for_run(c);
  const auto ready_md = test::closure_config(ready);
  ASSERT_TRUE(ready_md.prepared);
  EXPECT_EQ(ready_md.prepared->lattice_constant, prep.lattice_constant);
  EXPECT_NEAR(ready.material.density, rho0 * std::pow(a0 / prep.lattice_constant, 3), 1e-12 * rho0);
  EXPECT_LT(ready.material.density, rho0);
  EXPECT_FALSE(ready.material.spec->prepared());  // nothing left to do

  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 1;
  o.out_dir = test::scratch_dir("npt_whole");
  const auto one = app::run_mpm(c, o);
  EXPECT_EQ(figure(one, "md.lattice_constant_A"), prep.lattice_constant);
  EXPECT_EQ(figure(one, "md.lattice_constant_0K_A"), a0);
  EXPECT_EQ(figure(one, "md.prepare.pressure_GPa"), prep.pressure_gpa);
  EXPECT_NEAR(figure(one, "md.density"), ready.material.density, 1e-14 * ready.material.density);
  const std::string json = test::read_file(o.out_dir + "/run.json");
  EXPECT_NE(json.find("\"lattice_constant_0K_A\""), std::string::npos);
  // The run's own preparation is the one the deck's reading did before: the same points
  // to the bit as a run of the deck prepared beforehand.
  o.out_dir = test::scratch_dir("npt_ready");
  const auto pre = app::run_mpm(ready, o);
  ASSERT_EQ(one.state.particles.size(), pre.state.particles.size());
  for (std::size_t q = 0; q < one.state.particles.size(); ++q) {
    EXPECT_EQ(one.state.particles.mass[q], pre.state.particles.mass[q]) << q;
    EXPECT_EQ(one.state.particles.stress[0][q], pre.state.particles.stress[0][q]) << q;
  }
  EXPECT_EQ(test::read_file(o.out_dir + "/particles.csv"),
            test::read_file((test::scratch_root() / "npt_whole" / "particles.csv").string()));
  o.threads = 2;
  o.out_dir = test::scratch_dir("npt_two");
  const auto two = app::run_mpm(c, o);
  ASSERT_EQ(one.state.particles.size(), two.state.particles.size());
  for (std::size_t q = 0; q < one.state.particles.size(); ++q)
    EXPECT_EQ(one.state.particles.stress[0][q], two.state.particles.stress[0][q]) << q;

  // Stopped after a step and resumed: the same particles and the same prepared lattice.
  o.out_dir = test::scratch_dir("npt_parts");
  o.stop_after = 1;
  EXPECT_TRUE(app::run_mpm(c, o).interrupted);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm(c, o);
  ASSERT_EQ(rest.state.particles.size(), two.state.particles.size());
  for (std::size_t q = 0; q < rest.state.particles.size(); ++q)
    EXPECT_EQ(rest.state.particles.stress[0][q], two.state.particles.stress[0][q]) << q;
  EXPECT_EQ(figure(rest, "md.lattice_constant_A"), prep.lattice_constant);
}

void expect_ta_deck_error(const std::function<void(toml::table&)>& edit, const std::string& key,
                          const std::string& text) {
  try {
    test::deck_with(test::example("H5_ta_110_small.toml"), [&](toml::table& t) {
      t.erase("reference");
      edit(*t["material"]["md"].as_table());
    });
    ADD_FAILURE() << "accepted; expected an error on " << key;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(MdClosureCrystal, DeckKeysAreChecked) {
  expect_ta_deck_error([](toml::table& m) { m.insert_or_assign("lattice", "b2"); }, "material.md.lattice",
                       "one element");
  expect_ta_deck_error([](toml::table& m) { m.insert_or_assign("lattice", "bct"); }, "material.md.lattice", "bcc");
  expect_ta_deck_error([](toml::table& m) { m.insert_or_assign("c_over_a", 1.6); }, "material.md.c_over_a",
                       "an hcp lattice only");
  expect_ta_deck_error(
      [](toml::table& m) {
        m.insert_or_assign("orient", toml::array{toml::array{1, 1, 0}, toml::array{1, 1, 0}, toml::array{0, 0, 1}});
      },
      "material.md.orient", "orthogonal");
  expect_ta_deck_error([](toml::table& m) { m.insert_or_assign("temperature", 0.0); }, "material.md.prepare",
                       "temperature > 0");
  expect_ta_deck_error(
      [](toml::table& m) {
        m.insert_or_assign("prepare", "lattice");
        m.insert_or_assign("prepare_steps", 100);
      },
      "material.md.prepare_steps", "no use");
  expect_ta_deck_error([](toml::table& m) { m.insert_or_assign("prepare", "nvt"); }, "material.md.prepare", "npt");
}

// `mpmx check` names the boxes' crystal and says the run prepares them by NPT first.
TEST(MdClosureCrystal, CheckSaysTheCrystalAndTheNptPreparation) {
  const std::string cmd = std::string(MPMX_BINARY) + " check " + test::example("H5_ta_110_small.toml") + " 2>&1";
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  EXPECT_NE(out.find("3 tiles of bcc (108 atoms), x [1 1 0], y [-1 1 0], z [0 0 1]"), std::string::npos) << out;
  EXPECT_NE(out.find("prepare: one box by NPT at 10 K and 0 GPa for 10000 steps when the run starts"),
            std::string::npos)
      << out;
}

}  // namespace
