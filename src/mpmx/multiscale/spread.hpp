#pragma once
// Which MPI rank owns which material points of a multiscale closure, and the exchange
// of the per-point records the closure returns. Points are spread in contiguous blocks
// whose sizes differ by at most one; the records travel as doubles, a fixed number per
// point, so a closure of any dimension exchanges its own record (a 3x3 stress, the box)
// without this file knowing what it holds. One rank: one block, no exchange.
#include <cstddef>
#include <vector>

namespace mpmx::multiscale {

class Spread {
 public:
  explicit Spread(std::size_t points = 0);  // equal blocks over this job's ranks
  Spread(std::size_t points, int ranks, int rank);
  // Contiguous blocks of about equal total cost (cost[q]: point q's measured cost),
  // each of at least one point while there are enough; the same on every rank.
  static Spread balanced(const std::vector<double>& cost);
  static Spread balanced(const std::vector<double>& cost, int ranks, int rank);

  std::size_t points() const { return points_; }
  std::size_t begin() const { return starts_[rank_]; }
  std::size_t end() const { return starts_[rank_ + 1]; }
  std::size_t count() const { return end() - begin(); }
  bool owns(std::size_t q) const { return q >= begin() && q < end(); }
  int rank() const { return static_cast<int>(rank_); }
  // Block r is [start(r), start(r + 1)).
  std::size_t start(int r) const { return starts_[static_cast<std::size_t>(r)]; }
  int ranks() const { return static_cast<int>(starts_.size()) - 1; }
  bool operator==(const Spread& o) const { return starts_ == o.starts_; }

  // Collective: every rank's records (`width` doubles per point of its block) in point
  // order, on every rank.
  std::vector<double> all(const std::vector<double>& mine, int width) const;

 private:
  std::size_t points_ = 0, rank_ = 0;
  std::vector<std::size_t> starts_;  // block r is [starts_[r], starts_[r + 1])
};

}  // namespace mpmx::multiscale
