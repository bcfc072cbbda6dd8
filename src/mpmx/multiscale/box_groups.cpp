#include "mpmx/multiscale/box_groups.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <istream>
#include <iterator>
#include <map>
#include <optional>
#include <ostream>
#include <utility>

#include <fmt/format.h>

#include "mpmx/core/binary.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::multiscale {

namespace {

// splitmix64: the draw of auditors from (seed, group, step, point), the same anywhere.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

template <typename T>
void put(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <typename T>
T take(std::istream& in) {
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  if (!in) throw InputError("checkpoint: the shared boxes' groups are truncated");
  return v;
}

// The group whose key is nearest v and at most `tol` from it, with that distance (the
// lower key on a tie): the last key below v or the first at or above it.
std::optional<std::pair<std::size_t, double>> nearest_within(const std::map<double, std::size_t>& groups, double v,
                                                             double tol) {
  std::optional<std::pair<std::size_t, double>> best;
  const auto hi = groups.lower_bound(v);
  if (hi != groups.begin()) {
    const auto lo = std::prev(hi);
    if (v - lo->first <= tol) best = {lo->second, v - lo->first};
  }
  if (hi != groups.end() && hi->first - v <= tol && (!best || hi->first - v < best->second))
    best = {hi->second, hi->first - v};
  return best;
}

}  // namespace

double BoxGroups::distance(const Mat3& a, const Mat3& b) {
  double s = 0.0;
  for (int k = 0; k < 9; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(s);
}

BoxGroups::BoxGroups(const std::vector<double>& start, const ShareOptions& options) : opt_(options) {
  const std::size_t n = start.size();
  group_of_.assign(n, 0);
  deviation_.assign(n, 0.0);
  auditor_.assign(n, 0);
  std::map<double, std::size_t> first_of;  // each group's first start value -> the group
  for (std::size_t p = 0; p < n; ++p) {
    const double v = start[p];
    std::size_t g = members_.size();
    if (opt_.enabled && std::isfinite(v)) {
      // The group whose first start value is nearest within the tolerance: its box starts
      // from that value, and the difference is the member's deviation from the outset.
      if (const auto near = nearest_within(first_of, v, opt_.tolerance)) g = near->first, deviation_[p] = near->second;
      else first_of.emplace(v, g);
    }
    if (g == members_.size()) members_.emplace_back(), kept_.emplace_back(Mat3{});
    members_[g].push_back(p);
    group_of_[p] = g;
  }
  groups_initial_ = groups_max_ = members_.size();
}

BoxGroups::Split BoxGroups::split(const std::vector<Mat3>& L, double dt) {
  Split out;
  if (!opt_.enabled) return out;
  const double tol = opt_.tolerance;
  const std::size_t existing = members_.size();
  for (std::size_t g = 0; g < existing; ++g) {
    std::vector<std::size_t> stay, leave;
    for (std::size_t p : members_[g])
      (deviation_[p] + distance(L[p], kept_[g]) * dt > tol ? leave : stay).push_back(p);
    if (leave.empty()) continue;
    // The leavers in point order, each joining the first new group whose first member's
    // gradient agrees with its own within the tolerance.
    std::vector<std::vector<std::size_t>> clusters;
    for (std::size_t p : leave) {
      auto it = std::find_if(clusters.begin(), clusters.end(),
                             [&](const auto& c) { return distance(L[p], L[c.front()]) * dt <= tol; });
      if (it == clusters.end()) clusters.push_back({p});
      else it->push_back(p);
    }
    for (std::size_t p : leave) {
      deviation_[p] = 0.0;
      if (auditor_[p]) auditor_[p] = 0, out.dropped.push_back(p);
    }
    std::size_t first = 0;
    if (stay.empty()) {  // the first new group keeps the old box itself
      members_[g] = std::move(clusters[0]);
      first = 1;
    } else {
      members_[g] = std::move(stay);
    }
    for (std::size_t k = first; k < clusters.size(); ++k) {
      const std::size_t h = members_.size();
      for (std::size_t p : clusters[k]) group_of_[p] = h;
      members_.push_back(std::move(clusters[k]));
      kept_.push_back(kept_[g]);
      out.clones.push_back({g, h});
    }
  }
  groups_max_ = std::max(groups_max_, members_.size());
  return out;
}

BoxGroups::Merge BoxGroups::merge(const std::vector<BoxState>& state) {
  const std::size_t G = members_.size();
  Merge out;
  out.index.resize(G);
  out.size_before.resize(G);
  for (std::size_t g = 0; g < G; ++g) out.index[g] = g, out.size_before[g] = members_[g].size();
  if (!opt_.enabled || !opt_.by_state || G < 2) return out;
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> survivor(G, none);
  std::multimap<double, std::size_t> live;  // the survivors by their box's lx strain
  for (std::size_t h = 0; h < G; ++h) {
    // The room the members have left: a merge moves them by the shapes' difference.
    double used = 0.0;
    for (std::size_t p : members_[h]) used = std::max(used, deviation_[p]);
    const double room = opt_.tolerance - used;
    const BoxState& a = state[h];
    std::size_t best = none;
    double moved = 0.0;
    if (room > 0.0 && std::isfinite(a.shape[0])) {
      for (auto it = live.lower_bound(a.shape[0] - room); it != live.end() && it->first <= a.shape[0] + room; ++it) {
        const std::size_t g = it->second;
        if (g > best) continue;  // the earliest survivor that fits
        const BoxState& b = state[g];
        double d = 0.0, ds = 0.0;
        for (int k = 0; k < 6; ++k) d = std::max(d, std::abs(a.shape[k] - b.shape[k]));
        for (int k = 0; k < 9; ++k) ds = std::max(ds, std::abs(a.stress[k] - b.stress[k]));
        if (d <= room && ds <= opt_.state_stress && std::abs(a.energy - b.energy) <= opt_.state_energy)
          best = g, moved = d;
      }
    }
    if (best == none) {
      live.emplace(a.shape[0], h);
      continue;
    }
    survivor[h] = best;
    out.absorbed.emplace_back(h, best);
    for (std::size_t p : members_[h]) {
      deviation_[p] += moved;
      if (auditor_[p]) auditor_[p] = 0, out.dropped.push_back(p);
    }
  }
  if (out.absorbed.empty()) return out;
  std::sort(out.dropped.begin(), out.dropped.end());
  std::vector<std::vector<std::size_t>> members;
  std::vector<Mat3> kept;
  for (std::size_t g = 0; g < G; ++g) {
    if (survivor[g] != none) continue;
    out.index[g] = members.size();
    members.push_back(std::move(members_[g]));
    kept.push_back(kept_[g]);
  }
  for (const auto& [h, g] : out.absorbed) {
    out.index[h] = out.index[g];
    auto& m = members[out.index[g]];
    const std::size_t before = m.size();
    m.insert(m.end(), members_[h].begin(), members_[h].end());
    std::inplace_merge(m.begin(), m.begin() + static_cast<std::ptrdiff_t>(before), m.end());
  }
  members_ = std::move(members);
  kept_ = std::move(kept);
  for (std::size_t g = 0; g < members_.size(); ++g)
    for (std::size_t p : members_[g]) group_of_[p] = g;
  return out;
}

void BoxGroups::keep_means(const std::vector<Mat3>& L) {
  for (std::size_t g = 0; g < members_.size(); ++g) {
    Mat3 m{};
    for (std::size_t p : members_[g])
      for (int k = 0; k < 9; ++k) m[k] += L[p][k];
    const double inv = 1.0 / static_cast<double>(members_[g].size());
    for (int k = 0; k < 9; ++k) m[k] *= inv;
    kept_[g] = m;
  }
}

void BoxGroups::accumulate(const std::vector<Mat3>& L, double dt) {
  if (!opt_.enabled) return;
  for (std::size_t p = 0; p < group_of_.size(); ++p) deviation_[p] += distance(L[p], kept_[group_of_[p]]) * dt;
}

std::vector<std::size_t> BoxGroups::draw_auditors(std::int64_t step) {
  std::vector<std::size_t> drawn;
  if (!opt_.enabled || opt_.audit <= 0) return drawn;
  for (std::size_t g = 0; g < members_.size(); ++g) {
    const auto& m = members_[g];
    if (m.size() < 2) continue;
    std::vector<std::pair<std::uint64_t, std::size_t>> free;
    std::size_t have = 0;
    for (std::size_t p : m) {
      if (auditor_[p]) ++have;
      else free.emplace_back(mix(opt_.seed ^ mix(g ^ mix(static_cast<std::uint64_t>(step) ^ mix(p)))), p);
    }
    const std::size_t want = std::min<std::size_t>(static_cast<std::size_t>(opt_.audit), m.size() - 1);
    if (have >= want) continue;
    std::sort(free.begin(), free.end());
    for (std::size_t k = 0; k < want - have && k < free.size(); ++k) {
      auditor_[free[k].second] = 1;
      drawn.push_back(free[k].second);
    }
  }
  std::sort(drawn.begin(), drawn.end());
  return drawn;
}

void BoxGroups::save(std::ostream& out) const {
  put(out, static_cast<std::uint64_t>(group_of_.size()));
  put(out, static_cast<std::uint64_t>(members_.size()));
  put(out, static_cast<std::uint64_t>(groups_initial_));
  put(out, static_cast<std::uint64_t>(groups_max_));
  for (std::size_t g = 0; g < members_.size(); ++g) {
    put(out, static_cast<std::uint64_t>(members_[g].size()));
    for (std::size_t p : members_[g]) put(out, static_cast<std::uint64_t>(p));
    out.write(reinterpret_cast<const char*>(kept_[g].data()), sizeof(double) * 9);
  }
  out.write(reinterpret_cast<const char*>(deviation_.data()),
            static_cast<std::streamsize>(deviation_.size() * sizeof(double)));
  out.write(reinterpret_cast<const char*>(auditor_.data()), static_cast<std::streamsize>(auditor_.size()));
}

void BoxGroups::load(std::istream& in, const ShareOptions& options) {
  opt_ = options;
  const std::uint64_t n = read_count(in, sizeof(double) + 1 + 8, "shared-box points");
  const std::uint64_t groups = read_count(in, 8 + 72, "shared-box groups");
  if (groups > n || (n > 0 && groups == 0)) throw InputError(fmt::format("checkpoint: {} groups of {} points", groups, n));
  groups_initial_ = take<std::uint64_t>(in);
  groups_max_ = take<std::uint64_t>(in);
  members_.assign(groups, {});
  kept_.assign(groups, Mat3{});
  group_of_.assign(n, groups);
  for (std::size_t g = 0; g < groups; ++g) {
    const std::uint64_t m = read_count(in, 8, "shared-box members");
    if (m == 0) throw InputError("checkpoint: a shared-box group without members");
    for (std::uint64_t k = 0; k < m; ++k) {
      const auto p = take<std::uint64_t>(in);
      if (p >= n || group_of_[p] != groups || (k > 0 && p <= members_[g].back()))
        throw InputError(fmt::format("checkpoint: shared-box group {} names point {} out of place", g, p));
      members_[g].push_back(p);
      group_of_[p] = g;
    }
    in.read(reinterpret_cast<char*>(kept_[g].data()), sizeof(double) * 9);
  }
  for (std::size_t p = 0; p < n; ++p)
    if (group_of_[p] == groups) throw InputError(fmt::format("checkpoint: point {} is in no shared-box group", p));
  deviation_.assign(n, 0.0);
  auditor_.assign(n, 0);
  in.read(reinterpret_cast<char*>(deviation_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  in.read(reinterpret_cast<char*>(auditor_.data()), static_cast<std::streamsize>(n));
  if (!in) throw InputError("checkpoint: the shared boxes' groups are truncated");
}

}  // namespace mpmx::multiscale
