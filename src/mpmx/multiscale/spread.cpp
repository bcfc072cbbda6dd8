#include "mpmx/multiscale/spread.hpp"

#include "mpmx/core/ranks.hpp"

namespace mpmx::multiscale {

Spread::Spread(std::size_t points) : points_(points), rank_(static_cast<std::size_t>(ranks::rank())) {
  const auto n = static_cast<std::size_t>(ranks::size());
  starts_.resize(n + 1);
  for (std::size_t r = 0; r <= n; ++r) starts_[r] = r * points / n;  // sizes differ by at most one
}

std::vector<double> Spread::all(const std::vector<double>& mine, int width) const {
  std::vector<int> counts(starts_.size() - 1);
  for (std::size_t r = 0; r + 1 < starts_.size(); ++r)
    counts[r] = static_cast<int>((starts_[r + 1] - starts_[r]) * static_cast<std::size_t>(width));
  return ranks::all_gather(mine, counts);
}

}  // namespace mpmx::multiscale
