// ctest-label: unit
// dt = "cfl" with md_closure (issue 56): each step a whole number of MD steps chosen from
// the state (mpm/step_limit.hpp, c from the crystal's tangent modulus at the point's J),
// landing on the record times; the same particles on one and two threads and resumed bit
// for bit; a record time off the MD steps refused naming its key; `check` stating the
// first step and warning where a fixed dt exceeds the step a shocked state allows.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mpm/mpm_test_util.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/app/mpm/step_notes.hpp"
#include "mpmx/core/error.hpp"
#include "ms_test_util.hpp"

namespace {

using namespace mpmx;

// The 2-D flyer (4 x 2 cells of 1.1 nm, 108-atom boxes at 50 K) with [time] and [output]
// replaced.
std::string flyer(const std::string& time, const std::string& output, double speed = 0.5) {
  std::string d = test::flyer_2d_deck(50.0, 4);
  d = d.substr(0, d.find("[time]")) + time + output;
  const std::string v = "velocity = [0.5, 0.0]";
  d.replace(d.find(v), v.size(), "velocity = [" + std::to_string(speed) + ", 0.0]");
  return d;
}

app::MpmConfig cfl_flyer() {
  return app::read_mpm_deck_text(flyer("[time]\ndt = \"cfl\"\ncfl = 0.3\nend = 0.4\n", "[output]\ntimes = [0.25]\n"),
                                 "md_closure_cfl");
}

}  // namespace

TEST(MdClosureCfl, WholeMdStepsLandingOnRecordsSameOnTwoThreadsAndResumed) {
  const auto c = cfl_flyer();
  ASSERT_TRUE(c.cfl_dt);
  // The first step: 0.3 x 1.1 nm / (c0 + 0.5 km/s) in whole MD steps of 0.001 ps.
  EXPECT_NEAR(c.dt / 0.001, std::round(c.dt / 0.001), 1e-9);
  EXPECT_GT(c.dt, 0.04);
  EXPECT_LT(c.dt, 0.08);
  const auto [one, two] = test::same_on_one_and_two_threads<2>(c, false);
  EXPECT_EQ(one.state.time, 0.4);
  EXPECT_GE(one.steps, 6);
  // Whole MD steps: the boxes ran the 400 MD steps of 0.4 ps exactly (and 20 relaxing).
  EXPECT_EQ(std::get<std::int64_t>(test::closure_figure(one, "md.atom_steps_unshared")), 8 * 108 * (400 + 20));
  EXPECT_NE(one.time_steps.find("smallest / median / largest"), std::string::npos) << one.time_steps;
  EXPECT_EQ(one.time_steps, two.time_steps);

  // Records at 0.25 and 0.4 exactly; stopped after 3 steps and resumed, the same bits.
  app::RunOptions o = test::stopping_run("md_closure_cfl", 3);
  const auto first = app::run_mpm_dim<2>(c, o);
  ASSERT_TRUE(first.interrupted);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm_dim<2>(c, o);
  EXPECT_EQ(rest.steps, one.steps);
  EXPECT_EQ(rest.state.time, 0.4);
  test::expect_same_particles(one.state.particles, rest.state.particles);
  EXPECT_EQ(rest.time_steps, one.time_steps);  // the whole run's steps, the resumed part's too
  const std::string pvd = test::read_file(o.out_dir + "/particles.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.25\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.4\""), std::string::npos) << pvd;
  const std::string json = test::read_file(o.out_dir + "/run.json");
  for (const char* key : {"\"time_steps\"", "\"median\"", "\"limited_by\"", "\"shortest_by_state\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

// Merges by state take part in the step like the splits: the same bytes on one and two
// threads, and a run stopped and resumed goes on with the same groups and tallies.
TEST(MdClosureCfl, MergesByStateSameOnTwoThreadsAndResumed) {
  std::string text = flyer("[time]\ndt = \"cfl\"\ncfl = 0.3\nend = 0.4\n", "[output]\ntimes = [0.25]\n");
  text.replace(text.find("[boundary]"), 10,
               "[material.md.share]\ntolerance = 1e-3\nby_state = true\nstate_stress = 5.0\nstate_energy = 0.05\n"
               "[boundary]");
  const auto c = app::read_mpm_deck_text(text, "md_closure_merge");
  const auto [one, two] = test::same_on_one_and_two_threads<2>(c, false);
  const auto merges = std::get<std::int64_t>(test::closure_figure(one, "md.share.merges"));
  EXPECT_GT(merges, 0);
  EXPECT_EQ(std::get<std::int64_t>(test::closure_figure(two, "md.share.merges")), merges);
  // Stopped before the first merge: the resumed run's groups take the deck's options (a
  // resumed run builds no groups; they once came back with the defaults, tolerance 1e-4
  // and no merging, and the run went on differently).
  app::RunOptions o = test::stopping_run("md_closure_merge", 1);
  ASSERT_TRUE(app::run_mpm_dim<2>(c, o).interrupted);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm_dim<2>(c, o);
  test::expect_same_particles(one.state.particles, rest.state.particles);
  for (const char* key : {"md.share.merges", "md.share.merged_points", "md.atom_steps"})
    EXPECT_EQ(std::get<std::int64_t>(test::closure_figure(rest, key)),
              std::get<std::int64_t>(test::closure_figure(one, key)))
        << key;
  EXPECT_EQ(std::get<double>(test::closure_figure(rest, "md.share.merge_max_gpa")),
            std::get<double>(test::closure_figure(one, "md.share.merge_max_gpa")));
}

TEST(MdClosureCfl, ARecordTimeOffTheMdStepsIsRefused) {
  try {
    app::read_mpm_deck_text(flyer("[time]\ndt = \"cfl\"\nend = 0.4\n", "[output]\ntimes = [0.2505]\n"), "off");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("times"), std::string::npos) << m;
    EXPECT_NE(m.find("0.2505"), std::string::npos) << m;
    EXPECT_NE(m.find("not a whole number of MD steps"), std::string::npos) << m;
  }
  // max_volume_strain is dt = "cfl"'s alone.
  EXPECT_THROW(app::read_mpm_deck_text(flyer("[time]\ndt = 0.1\nmax_volume_strain = 0.1\nend = 0.4\n", ""), "fixed"),
               InputError);
}

TEST(MdClosureCfl, CheckStatesTheStepAndWarnsOfAFixedStepPastTheShockedLimit) {
  auto joined = [](const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  };
  const std::string cfl = joined(app::describe_time_step(cfl_flyer()));
  EXPECT_NE(cfl.find("time step: dt = \"cfl\" at cfl = 0.3"), std::string::npos) << cfl;
  EXPECT_NE(cfl.find("whole MD steps of 0.001"), std::string::npos) << cfl;
  EXPECT_EQ(cfl.find("warning"), std::string::npos) << cfl;
  // At 2.5 km/s: 0.12 ps is within the start's limit (1.1 / (4.7 + 2.5) = 0.15 ps), not
  // within the shocked crystal's (c about 8 km/s at J about 0.68).
  const auto fixed = app::read_mpm_deck_text(flyer("[time]\ndt = 0.12\nend = 0.36\n", "", 2.5), "fixed");
  const std::string f = joined(app::describe_time_step(fixed));
  EXPECT_NE(f.find("time step: dt = 0.12 fixed"), std::string::npos) << f;
  EXPECT_NE(f.find("shocked: a planar shock at up = 2.5"), std::string::npos) << f;
  EXPECT_NE(f.find("warning: time.dt = 0.12 exceeds"), std::string::npos) << f;
  const auto small = app::read_mpm_deck_text(flyer("[time]\ndt = 0.05\nend = 0.35\n", "", 2.5), "small");
  const std::string s = joined(app::describe_time_step(small));
  EXPECT_EQ(s.find("warning"), std::string::npos) << s;
  EXPECT_NE(s.find("is within it"), std::string::npos) << s;
  // The tensor viscosity at a front one cell wide tightens the limit to about 0.02 ps
  // (Q = 1.5 c + 2 up = 17 km/s): the same 0.05 is past it.
  const auto viscous = app::read_mpm_deck_text(
      flyer("[viscosity]\ntensor = true\n[time]\ndt = 0.05\nend = 0.35\n", "", 2.5), "viscous");
  const std::string v = joined(app::describe_time_step(viscous));
  EXPECT_NE(v.find("with the tensor viscosity at a front one cell wide"), std::string::npos) << v;
  EXPECT_NE(v.find("warning: time.dt = 0.05 exceeds"), std::string::npos) << v;
}
