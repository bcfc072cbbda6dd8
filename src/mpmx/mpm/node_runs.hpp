#pragma once
// Grid passes that threads share without changing a bit of the result: work over runs
// built apart and joined in order, and byte marks dilated over a node's 3^d box.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "mpmx/mpm/grid.hpp"

namespace mpmx::mpm {

// [0, count) split into runs that threads build apart, f(part, begin, end) each into its
// own part (which f clears first). Joined by the caller in run order, the parts are what
// one pass in order would build, for any thread count.
template <class Part, class F>
void build_in_runs(std::size_t count, int threads, std::vector<Part>& parts, F&& f) {
  const std::size_t P = std::max<std::size_t>(1, std::min<std::size_t>(count, 4 * static_cast<std::size_t>(std::max(threads, 1))));
  parts.resize(P);
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (std::size_t k = 0; k < P; ++k) f(parts[k], count * k / P, count * (k + 1) / P);
}

// The marks in `a` dilated over the 3^d box of every marked node, one axis at a time,
// with `b` as scratch; returns the array that holds the result (a or b). Ghost nodes are
// never marked, so a step that wraps onto a neighbouring line's ghost reads a zero.
template <int Dim, class Mark>
Mark* dilate_marks(const Grid<Dim>& g, Mark* a, Mark* b, int threads) {
  const std::size_t n = g.storage;
  for (int d = 0; d < Dim; ++d) {
    const std::size_t s = static_cast<std::size_t>(g.stride[d]);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t i = 0; i < n; ++i)
      b[i] = static_cast<Mark>(a[i] | (i >= s ? a[i - s] : 0) | (i + s < n ? a[i + s] : 0));
    std::swap(a, b);
  }
  return a;
}

}  // namespace mpmx::mpm
