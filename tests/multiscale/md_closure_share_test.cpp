// ctest-label: unit
// Boxes shared by history (multiscale/box_groups.hpp) inside the MD closure: at 0 K a
// group of points with one history gives each member exactly the stress its own box
// would, and a member that departs continues from an exact copy of its group's box.
#include <gtest/gtest.h>

#include <vector>

#include "mpmx/mpm/points.hpp"
#include "mpmx/multiscale/md_closure.hpp"
#include "multiscale/ms_test_util.hpp"

using namespace mpmx;

namespace {

multiscale::MdClosureConfig bar_config(bool share, double tolerance = 1e-4) {
  auto md = test::closure_config(test::tiny_bar(4, 2, 2));
  md.threads = 1;
  md.share.enabled = share;
  md.share.tolerance = tolerance;
  md.share.audit = 0;
  return md;
}

// Each step's gradient of every point (1/ps as continuum units here: nm_ps_GPa).
using History = std::vector<std::vector<double>>;

std::vector<double> run_closure(const multiscale::MdClosureConfig& md, const History& gradients,
                                std::vector<double> strain, multiscale::MdClosure<1>** keep = nullptr) {
  static std::vector<std::unique_ptr<multiscale::MdClosure<1>>> kept;
  auto m = std::make_unique<multiscale::MdClosure<1>>(md);
  mpm::Particles<1> p;
  p.resize(strain.size());
  p.strain[0] = strain;
  for (std::size_t q = 0; q < strain.size(); ++q) p.mass[q] = p.volume[q] = 1.0;
  m->initialize(mpm::points(p));
  for (const auto& g : gradients) {
    p.grad_v[0] = g;
    m->update_stress(mpm::points(p), 0.02);
  }
  if (keep) *keep = m.get(), kept.push_back(std::move(m));
  return p.stress[0];
}

}  // namespace

TEST(MdClosureShare, IdenticalPointsAtZeroKelvinGetTheirUnsharedStressBitForBit) {
  const History h{{-0.05, -0.05, -0.05, -0.05}, {-0.05, -0.05, -0.05, -0.05}, {0.02, 0.02, 0.02, 0.02}};
  multiscale::MdClosure<1>* shared = nullptr;
  const auto s = run_closure(bar_config(true), h, {0.0, 0.0, 0.0, 0.0}, &shared);
  const auto u = run_closure(bar_config(false), h, {0.0, 0.0, 0.0, 0.0});
  EXPECT_EQ(s, u);
  EXPECT_EQ(shared->groups().groups(), 1u);
  EXPECT_EQ(shared->atom_steps() * 4, shared->atom_steps_unshared());
}

// Tolerance 0: the first departure splits the group; each new group starts from a copy
// of the box as it was, then follows its own gradient. So a point's stress equals that of
// a box of its own driven by the group's mean before the split and its own gradient after.
TEST(MdClosureShare, ADepartingMemberContinuesFromAnExactCopy) {
  const double a = -0.05, b = -0.03;
  const History shared_history{{a, a}, {a, a}, {a, b}, {a, b}};
  multiscale::MdClosure<1>* m = nullptr;
  const auto s = run_closure(bar_config(true, 0.0), shared_history, {0.0, 0.0}, &m);
  EXPECT_EQ(m->groups().groups(), 2u);
  EXPECT_EQ(m->groups().groups_initial(), 1u);
  const auto stayer = run_closure(bar_config(false), {{a}, {a}, {a}, {a}}, {0.0});
  const auto leaver = run_closure(bar_config(false), {{a}, {a}, {b}, {b}}, {0.0});
  EXPECT_EQ(s[0], stayer[0]);
  EXPECT_EQ(s[1], leaver[0]);
}

// With a tolerance the member stays until its deviation passes it: the box follows the
// mean meanwhile, and the members' stresses differ from their own boxes' by what the
// audit measures.
TEST(MdClosureShare, TheAuditMeasuresTheSharingsError) {
  auto md = bar_config(true, 1e-3);
  md.share.audit = 1;
  const History h(6, std::vector<double>{-0.05, -0.04});
  multiscale::MdClosure<1>* m = nullptr;
  const auto s = run_closure(md, h, {0.0, 0.0}, &m);
  const auto own1 = run_closure(bar_config(false), History(6, std::vector<double>{-0.04}), {0.0});
  ASSERT_EQ(m->groups().groups(), 1u);  // 0.01 / ps x 0.12 ps / 2 = 6e-4 < 1e-3: never split
  EXPECT_TRUE(std::isfinite(m->audit_rel_rms()));
  EXPECT_GT(m->audit_max_gpa(), 0.0);
  // The shared stress is the mean history's; the difference to the point's own box is
  // of the order the audit reports (its largest component difference).
  EXPECT_NE(s[1], own1[0]);
  EXPECT_LT(std::abs(s[1] - own1[0]), 3.0 * m->audit_max_gpa() + 1e-12);
}

// By state: two points leave one group by different paths (past the tolerance) and come
// back to one shape; at 0 K their boxes then hold one state and merge, and from there the
// two points take one box's stress.
TEST(MdClosureShare, PathsThatMeetAgainMergeByState) {
  auto md = bar_config(true, 1e-3);
  md.share.by_state = true;
  // Apart by 0.08 / ps x 0.02 ps = 1.6e-3 a step: they part at the second step, the one
  // compressed while the other expands, then the other way round until their boxes have
  // one shape again (after five steps), then alike.
  const double a = -0.05, b = 0.03;
  History h(3, std::vector<double>{a, b});
  for (int k = 0; k < 2; ++k) h.push_back({b, a});
  for (int k = 0; k < 2; ++k) h.push_back({a, a});
  multiscale::MdClosure<1>* m = nullptr;
  const auto s = run_closure(md, h, {0.0, 0.0}, &m);
  EXPECT_EQ(m->groups().groups_max(), 2u);
  EXPECT_EQ(m->groups().groups(), 1u);
  EXPECT_EQ(m->merges(), 1);
  EXPECT_EQ(m->merged_points(), 1);
  EXPECT_EQ(s[0], s[1]);
  EXPECT_LT(m->atom_steps(), m->atom_steps_unshared());
  // Without by_state they stay apart, each on its own box: the two paths leave the atoms
  // in slightly different motion (0.2% apart in stress), and the merged pair takes the
  // survivor's (point 0's box) to the last bit.
  md.share.by_state = false;
  multiscale::MdClosure<1>* apart = nullptr;
  const auto u = run_closure(md, h, {0.0, 0.0}, &apart);
  EXPECT_EQ(apart->groups().groups(), 2u);
  EXPECT_EQ(apart->merges(), 0);
  EXPECT_NE(u[0], u[1]);
  EXPECT_NEAR(u[0], u[1], 0.01 * std::abs(u[0]));
  EXPECT_EQ(s[0], u[0]);
}

// A merge of hot boxes keeps their members' mean energy (eq. 7.11's books, 1-D with the
// consistency on): two 300 K points part and meet again as above, their boxes now at
// different energies (their paths heated them differently); the survivor is owed what
// makes it their mean, and a macro step at rest puts exactly that into it.
TEST(MdClosureShare, AMergeOfHotBoxesKeepsTheirMembersMeanEnergy) {
  auto md = test::closure_config(test::tiny_bar(4, 2, 2, 300.0));
  md.threads = 1;
  md.share.tolerance = 1e-3;
  md.share.audit = 0;
  md.share.state_stress = 1e3;  // any state: the merge comes when the shapes meet
  md.share.state_energy = 1e3;
  md.energy_consistency = 1;
  const double a = -0.05, b = 0.03;
  History h(3, std::vector<double>{a, b});
  for (int k = 0; k < 2; ++k) h.push_back({b, a});
  auto energy = [](const md::System& box) { return box.potential_energy() + box.thermal_kinetic_energy(); };
  // Apart: both boxes after the five steps, as the merging run has them before it merges.
  multiscale::MdClosure<1>* apart = nullptr;
  run_closure(md, h, {0.0, 0.0}, &apart);
  ASSERT_EQ(apart->groups().groups(), 2u);
  ASSERT_EQ(apart->energy_shortfall_ev(), 0.0);  // nothing owed: each box holds its energy
  const double e0 = energy(*apart->box(0)), e1 = energy(*apart->box(1));
  // Two paths, two energies (1.4e-3 eV apart in 111 eV), far beyond the check's 1e-9.
  EXPECT_GT(std::abs(e0 - e1), 1e-5 * std::abs(e0));
  // Merged at the fifth step's end, then a step at rest (no work): the survivor holds the mean.
  md.share.by_state = true;
  h.push_back({0.0, 0.0});
  multiscale::MdClosure<1>* merged = nullptr;
  run_closure(md, h, {0.0, 0.0}, &merged);
  ASSERT_EQ(merged->merges(), 1);
  ASSERT_EQ(merged->groups().groups(), 1u);
  EXPECT_NEAR(energy(*merged->box(0)), 0.5 * (e0 + e1), 1e-9 * std::abs(e0));
}
