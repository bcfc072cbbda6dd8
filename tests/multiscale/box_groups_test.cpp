// ctest-label: unit
// The bookkeeping of history-shared boxes: who starts together, who leaves when, where
// leavers go, and that a group's kept gradient never holds a leaver's.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "mpmx/core/error.hpp"
#include "mpmx/multiscale/box_groups.hpp"

using namespace mpmx;
using multiscale::BoxGroups;
using multiscale::ShareOptions;

namespace {

BoxGroups::Mat3 shear(double rate) {
  BoxGroups::Mat3 m{};
  m[1] = rate;
  return m;
}

}  // namespace

TEST(BoxGroups, PointsThatStartAlikeShareOneGroup) {
  const BoxGroups g({0.0, -0.01, 0.0, -0.01, 0.02}, ShareOptions{});
  ASSERT_EQ(g.groups(), 3u);
  EXPECT_EQ(g.members(0), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(g.members(2), (std::vector<std::size_t>{4}));
  ShareOptions off;
  off.enabled = false;
  EXPECT_EQ(BoxGroups({0.0, 0.0, 0.0}, off).groups(), 3u);
}

// A start within the tolerance of a group's first value joins the nearest such group and
// carries the difference as its deviation; tolerance 0 groups equal values only.
TEST(BoxGroups, StartsWithinTheToleranceShareTheNearestGroup) {
  ShareOptions o;
  o.tolerance = 1e-4;
  const BoxGroups g({0.0, 5e-5, 2e-4, -9e-5, 1.5e-4, 1e-4 + 1e-12}, o);
  ASSERT_EQ(g.groups(), 2u);
  EXPECT_EQ(g.members(0), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{2, 4, 5}));  // 1.5e-4 is nearer 2e-4 than 0
  EXPECT_EQ(g.deviation(0), 0.0);
  EXPECT_DOUBLE_EQ(g.deviation(1), 5e-5);
  EXPECT_DOUBLE_EQ(g.deviation(3), 9e-5);
  EXPECT_DOUBLE_EQ(g.deviation(4), 5e-5);
  // One past the tolerance from 0 (1e-4 + 1e-12) and within it from 2e-4.
  EXPECT_NEAR(g.deviation(5), 1e-4 - 1e-12, 1e-18);
  o.tolerance = 0.0;
  const BoxGroups exact({0.0, 1e-13, 0.0, 2e-4}, o);
  ASSERT_EQ(exact.groups(), 3u);
  EXPECT_EQ(exact.members(0), (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(exact.deviation(2), 0.0);
}

// With tolerance 0 every member leaves at its first departure from what the group kept;
// members whose gradients are equal leave together, into one new group.
TEST(BoxGroups, ToleranceZeroSplitsAtTheFirstDeparture) {
  ShareOptions o;
  o.tolerance = 0.0;
  BoxGroups g(std::vector<double>(6, 0.0), o);
  std::vector<BoxGroups::Mat3> L(6, BoxGroups::Mat3{});
  auto s = g.split(L, 0.01);  // nobody departs from the rest the group kept
  EXPECT_TRUE(s.clones.empty());
  g.keep_means(L);
  g.accumulate(L, 0.01);
  L[2] = L[4] = shear(1e-6);
  L[5] = shear(-1e-6);
  s = g.split(L, 0.01);
  ASSERT_EQ(g.groups(), 3u);
  EXPECT_EQ(g.members(0), (std::vector<std::size_t>{0, 1, 3}));
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{2, 4}));
  EXPECT_EQ(g.members(2), (std::vector<std::size_t>{5}));
  ASSERT_EQ(s.clones.size(), 2u);
  EXPECT_EQ(s.clones[0].from, 0u);
  EXPECT_EQ(s.clones[0].to, 1u);
  EXPECT_EQ(s.clones[1].to, 2u);
  // The group's box steps with its stayers' mean: the leavers' gradients are not in it.
  g.keep_means(L);
  EXPECT_EQ(g.kept(0), BoxGroups::Mat3{});
  EXPECT_EQ(g.kept(1), shear(1e-6));
}

// A member driven off its group leaves at the step its deviation passes the tolerance.
TEST(BoxGroups, AMemberLeavesWhenItsDeviationPassesTheTolerance) {
  ShareOptions o;
  o.tolerance = 1e-4;
  BoxGroups g(std::vector<double>(3, 0.0), o);
  const double dt = 0.01, rate = 0.4e-3;  // point 2 departs by 4e-6 per step: 25 steps to 1e-4
  std::vector<BoxGroups::Mat3> L(3, BoxGroups::Mat3{});
  L[2] = shear(rate);
  int left_at = -1;
  for (int step = 1; step <= 40 && left_at < 0; ++step) {
    const auto s = g.split(L, dt);
    if (!s.clones.empty()) left_at = step;
    g.keep_means(L);
    g.accumulate(L, dt);
  }
  // The kept gradient is the mean of three, so the stayers deviate by rate/3 per unit
  // time and the driven member by 2 rate/3: it passes 1e-4 at step ceil(1e-4 / (2/3 rate dt)).
  const double per_step = 2.0 / 3.0 * rate * dt;
  EXPECT_EQ(left_at, static_cast<int>(std::ceil(1e-4 / per_step - 1e-9))) << per_step;
  ASSERT_EQ(g.groups(), 2u);
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{2}));
  EXPECT_EQ(g.deviation(2), 0.0 + BoxGroups::distance(L[2], g.kept(1)) * dt);
}

TEST(BoxGroups, WhenEveryMemberLeavesTheFirstNewGroupKeepsTheBox) {
  ShareOptions o;
  o.tolerance = 0.0;
  BoxGroups g(std::vector<double>(4, 0.0), o);
  std::vector<BoxGroups::Mat3> L{shear(1.0), shear(1.0), shear(2.0), shear(2.0)};
  const auto s = g.split(L, 0.01);
  ASSERT_EQ(g.groups(), 2u);
  EXPECT_EQ(g.members(0), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{2, 3}));
  ASSERT_EQ(s.clones.size(), 1u);
  EXPECT_EQ(s.clones[0].from, 0u);
}

TEST(BoxGroups, AuditorsAreDrawnFromTheSeedAndDroppedWhenTheyLeave) {
  ShareOptions o;
  o.audit = 2;
  BoxGroups a(std::vector<double>(10, 0.0), o), b(std::vector<double>(10, 0.0), o);
  const auto da = a.draw_auditors(0), db = b.draw_auditors(0);
  EXPECT_EQ(da.size(), 2u);
  EXPECT_EQ(da, db);
  EXPECT_TRUE(a.draw_auditors(1).empty());  // the group has its two
  o.seed = 7;
  BoxGroups c(std::vector<double>(10, 0.0), o);
  const auto dc = c.draw_auditors(0);
  EXPECT_EQ(dc.size(), 2u);
  // An auditor that leaves its group ends its audit.
  o.tolerance = 0.0;
  BoxGroups d(std::vector<double>(10, 0.0), o);
  const auto dd = d.draw_auditors(0);
  std::vector<BoxGroups::Mat3> L(10, BoxGroups::Mat3{});
  L[dd[0]] = shear(1.0);
  const auto s = d.split(L, 0.01);
  EXPECT_EQ(s.dropped, (std::vector<std::size_t>{dd[0]}));
  EXPECT_FALSE(d.auditor(dd[0]));
}

TEST(BoxGroups, SavedGroupsLoadWholeAndDamagedOnesAreRefused) {
  ShareOptions o;
  o.tolerance = 0.0;
  BoxGroups g(std::vector<double>(5, 0.0), o);
  std::vector<BoxGroups::Mat3> L{shear(1.0), {}, shear(1.0), {}, shear(3.0)};
  g.split(L, 0.01);
  g.keep_means(L);
  g.accumulate(L, 0.01);
  g.draw_auditors(3);
  std::stringstream out;
  g.save(out);
  BoxGroups back;
  back.load(out, o);
  ASSERT_EQ(back.groups(), g.groups());
  EXPECT_EQ(back.options().tolerance, 0.0);  // the deck's, not the default 1e-4
  for (std::size_t k = 0; k < g.groups(); ++k) {
    EXPECT_EQ(back.members(k), g.members(k));
    EXPECT_EQ(back.kept(k), g.kept(k));
  }
  for (std::size_t p = 0; p < 5; ++p) {
    EXPECT_EQ(back.deviation(p), g.deviation(p));
    EXPECT_EQ(back.auditor(p), g.auditor(p));
  }
  std::string bytes = out.str();
  std::stringstream cut(bytes.substr(0, bytes.size() / 2));
  EXPECT_THROW(back.load(cut, o), InputError);
}

// By state: a group whose box reached an earlier group's state (shape within the room its
// members have left, energy and stress within the noise bounds) is absorbed by the
// earliest such group; its members carry the shapes' difference as deviation.
TEST(BoxGroups, GroupsWhoseBoxesMeetInOneStateMerge) {
  ShareOptions o;
  o.tolerance = 1e-3;
  o.by_state = true;
  o.audit = 1;
  BoxGroups g({0.5, 0.0, 8e-4, 0.0, 0.9, 0.9}, o);  // {0}, {1, 2, 3} (2 at 8e-4), {4, 5}
  ASSERT_EQ(g.groups(), 3u);
  EXPECT_EQ(g.draw_auditors(1).size(), 2u);  // one in each group of two or more
  auto state = [](double lx, double e, double sxx) {
    multiscale::BoxState s;
    s.shape = {lx, 1.0, 1.0, 0.0, 0.0, 0.0};
    s.energy = e, s.stress[0] = sxx;
    return s;
  };
  // Group 1 is 5e-4 from group 0, past the room its member 2 has (1e-3 - 8e-4): it stays.
  // Group 2 is 1e-4 from group 0 with its energy and stress within the bounds: absorbed.
  std::vector<multiscale::BoxState> s{state(1.0, -3.5, -10.0), state(1.0005, -3.5, -10.0),
                                      state(1.0001, -3.505, -10.9)};
  auto m = g.merge(s);
  ASSERT_EQ(g.groups(), 2u);
  EXPECT_EQ(m.index, (std::vector<std::size_t>{0, 1, 0}));
  ASSERT_EQ(m.absorbed.size(), 1u);
  EXPECT_EQ(m.absorbed[0], (std::pair<std::size_t, std::size_t>{2, 0}));
  EXPECT_EQ(m.size_before, (std::vector<std::size_t>{1, 3, 2}));
  EXPECT_EQ(g.members(0), (std::vector<std::size_t>{0, 4, 5}));
  EXPECT_EQ(g.members(1), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(g.group_of(5), 0u);
  EXPECT_NEAR(g.deviation(4), 1e-4, 1e-15);
  EXPECT_EQ(m.dropped.size(), 1u);  // the absorbed group's auditor ends with its box
  EXPECT_FALSE(g.auditor(4) || g.auditor(5));
  // A stress past state_stress, or an energy past state_energy, keeps groups apart.
  BoxGroups h({0.0, 0.5}, o);
  EXPECT_TRUE(h.merge({state(1.0, -3.5, -10.0), state(1.0, -3.5, -11.1)}).absorbed.empty());
  EXPECT_TRUE(h.merge({state(1.0, -3.5, -10.0), state(1.0, -3.52, -10.0)}).absorbed.empty());
  EXPECT_EQ(h.merge({state(1.0, -3.5, -10.0), state(1.0, -3.5, -10.0)}).absorbed.size(), 1u);
  // Without by_state nothing merges.
  o.by_state = false;
  BoxGroups off({0.0, 0.5}, o);
  const auto none = off.merge({state(1.0, -3.5, -10.0), state(1.0, -3.5, -10.0)});
  EXPECT_TRUE(none.absorbed.empty());
  EXPECT_EQ(off.groups(), 2u);
}
