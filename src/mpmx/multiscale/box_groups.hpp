#pragma once
// History-shared boxes: the bookkeeping of which material points share one micro-model
// box (an MD box in DDMP-MD), whatever the model. Points whose boxes would start from
// states within the tolerance of each other form one group with one box, started from
// its first member's state; each member's start difference is its deviation from the
// outset (a profile such as tanh gives no two points the same start to the last bit,
// and a group for every last bit was most of H2's boxes). Each macro step
//   1. who leaves is decided first, against the gradient the group kept (the one its box
//      followed last step): a member whose deviation D_p + |L_p - L_kept| dt would pass
//      the tolerance leaves, so the box never steps with a leaver's gradient in its mean;
//   2. the members leaving one group in one step are gathered in point order into new
//      groups of members whose gradients agree within the tolerance (|L_p - L_first| dt),
//      each starting from a copy of the old box, exact up to this moment (when every
//      member leaves, the first new group keeps the old box itself);
//   3. each group's box steps with its members' mean gradient, which it keeps;
//   4. every member accumulates its deviation D_p += |L_p - L_box| dt (a strain).
// Without by_state groups never merge. Every decision reads replicated numbers (the
// gradients, and with by_state the boxes' published states), the same on every rank and
// thread: the groups are replicated, the boxes live where their group is run.
//
// By state (`by_state`): after the boxes step, a group whose box has reached the state of
// an earlier group's box (shape within the members' room left under the tolerance, energy
// per atom and stress within the boxes' noise, state_energy and state_stress) is absorbed
// by it: its members go on with that box, each member's deviation grows by the shapes'
// difference (so it still bounds how far the member's own history is from its box), and
// its box ends. Behind a planar shock the points reach one state by different paths; by
// history alone no two of them share again. Every decision reads the replicated states.
//
// Audits: up to `audit` members of every group of more than one point also run a private
// box with their own gradient (not fed back); its stress against the group's is the
// sharing's own error, measured while it runs. Auditors are drawn from the deck's seed.
#include <array>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace mpmx::multiscale {

struct ShareOptions {
  bool enabled = true;     // false: one box per point
  double tolerance = 1e-4;  // strain: the deviation a member may accumulate
  int audit = 4;            // members per group of more than one point on private boxes as well
  std::uint64_t seed = 1;   // draws the auditors
  bool by_state = false;       // groups whose boxes reach one state merge
  double state_stress = 1.0;   // GPa: the largest difference of a stress component in a merge
  double state_energy = 0.01;  // eV per atom: the largest energy difference in a merge
};

// A group's box as a merge compares it: its shape (lx, ly, lz, xy, xz, yz) over the
// unstrained box's edge, its energy per atom (eV) and its stress (GPa, box frame).
struct BoxState {
  std::array<double, 6> shape{};
  double energy = 0.0;
  std::array<double, 9> stress{};
};

class BoxGroups {
 public:
  using Mat3 = std::array<double, 9>;  // row-major velocity gradient (1/ps)

  // A new group g that starts as a copy of group `from`'s box.
  struct Clone {
    std::size_t from, to;
  };

  BoxGroups() = default;
  // Groups of points whose `start` values (strains) are within the tolerance: in point
  // order, each point joins the group whose first value is nearest within it (its
  // deviation that difference), or starts a new one; a group per point when sharing is
  // off. With tolerance 0, the points of equal values.
  BoxGroups(const std::vector<double>& start, const ShareOptions& options);

  // What a split changed: the new groups, in order, each to start from a copy of its
  // parent's box; the auditors that left their group (their private boxes end).
  struct Split {
    std::vector<Clone> clones;
    std::vector<std::size_t> dropped;
  };
  // Steps 1-2 for this macro step's gradients (every point's, 1/ps) over dt (ps).
  Split split(const std::vector<Mat3>& L, double dt);
  // What a merge by state changed: each old group's new index (an absorbed group's is
  // its survivor's; the survivors keep their order), the absorbed groups with their
  // survivors (old indices, in order), the auditors that left with their group.
  struct Merge {
    std::vector<std::size_t> index;
    std::vector<std::pair<std::size_t, std::size_t>> absorbed;
    std::vector<std::size_t> dropped;
    std::vector<std::size_t> size_before;  // each old group's members
  };
  // Step 5 (by_state): groups whose boxes are in one state, `state` the boxes' after this
  // macro step. Nothing changes without by_state (index the identity).
  Merge merge(const std::vector<BoxState>& state);
  // Step 3: each group's mean gradient (its members' in point order), kept.
  void keep_means(const std::vector<Mat3>& L);
  // Step 4.
  void accumulate(const std::vector<Mat3>& L, double dt);
  // Auditors for every group of more than one point that has fewer than `audit` among
  // its members (after a split): the points newly drawn, each to start a private box
  // from its group's box. `step` enters the draw so that refills differ.
  std::vector<std::size_t> draw_auditors(std::int64_t step);

  std::size_t groups() const { return members_.size(); }
  std::size_t points() const { return group_of_.size(); }
  const std::vector<std::size_t>& members(std::size_t g) const { return members_[g]; }
  std::size_t group_of(std::size_t p) const { return group_of_[p]; }
  const Mat3& kept(std::size_t g) const { return kept_[g]; }
  double deviation(std::size_t p) const { return deviation_[p]; }
  bool auditor(std::size_t p) const { return auditor_[p] != 0; }
  std::size_t groups_max() const { return groups_max_; }
  std::size_t groups_initial() const { return groups_initial_; }
  const ShareOptions& options() const { return opt_; }

  // |A - B| (Frobenius).
  static double distance(const Mat3& a, const Mat3& b);

  void save(std::ostream& out) const;
  // The groups of a saved run, under the deck's options (the record holds the groups, not
  // the options). Throws InputError on a damaged or inconsistent record.
  void load(std::istream& in, const ShareOptions& options);

 private:
  ShareOptions opt_;
  std::vector<std::vector<std::size_t>> members_;  // ascending point indices
  std::vector<Mat3> kept_;                          // the gradient each group's box followed last
  std::vector<std::size_t> group_of_;
  std::vector<double> deviation_;
  std::vector<std::uint8_t> auditor_;
  std::size_t groups_initial_ = 0, groups_max_ = 0;
};

}  // namespace mpmx::multiscale
