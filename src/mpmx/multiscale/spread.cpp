#include "mpmx/multiscale/spread.hpp"

#include "mpmx/core/ranks.hpp"

namespace mpmx::multiscale {

Spread::Spread(std::size_t points) : Spread(points, ranks::size(), ranks::rank()) {}

Spread::Spread(std::size_t points, int ranks, int rank) : points_(points), rank_(static_cast<std::size_t>(rank)) {
  const auto n = static_cast<std::size_t>(ranks);
  starts_.resize(n + 1);
  for (std::size_t r = 0; r <= n; ++r) starts_[r] = r * points / n;  // sizes differ by at most one
}

Spread Spread::balanced(const std::vector<double>& cost) {
  return balanced(cost, ranks::size(), ranks::rank());
}

Spread Spread::balanced(const std::vector<double>& cost, int ranks, int rank) {
  Spread s(cost.size(), ranks, rank);
  const std::size_t n = s.starts_.size() - 1, points = cost.size();
  double total = 0.0;
  for (double c : cost) total += c;
  if (!(total > 0.0)) return s;
  // Block r - 1 ends at the first point whose middle lies past r / n of the total cost;
  // every block keeps at least one point while there are points to give.
  double running = 0.0;
  std::size_t q = 0;
  for (std::size_t r = 1; r < n; ++r) {
    const double target = total * static_cast<double>(r) / static_cast<double>(n);
    const std::size_t at_least = s.starts_[r - 1] + (points >= n ? 1 : 0);
    const std::size_t at_most = points - (points >= n ? n - r : 0);
    while (q < points && (q < at_least || running + 0.5 * cost[q] < target) && q < at_most) running += cost[q++];
    s.starts_[r] = q;
  }
  s.starts_[n] = points;
  return s;
}

std::vector<double> Spread::all(const std::vector<double>& mine, int width) const {
  std::vector<int> counts(starts_.size() - 1);
  for (std::size_t r = 0; r + 1 < starts_.size(); ++r)
    counts[r] = static_cast<int>((starts_[r + 1] - starts_[r]) * static_cast<std::size_t>(width));
  return ranks::all_gather(mine, counts);
}

}  // namespace mpmx::multiscale
