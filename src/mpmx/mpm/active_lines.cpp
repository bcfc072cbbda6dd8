#include "mpmx/mpm/active_lines.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <climits>
#include <cstdint>
#include <vector>

namespace mpmx::mpm {

template <int Dim>
void mark_active_lines(Grid<Dim>& g, const Stencil<Dim>& st, int threads) {
  static_assert(Dim > 1);
  if (*std::min_element(st.box.begin(), st.box.end()) < 1) {  // no box widths: the whole grid
    std::fill(g.active_lo.begin(), g.active_lo.end(), 0);
    std::fill(g.active_hi.begin(), g.active_hi.end(), g.cells[0]);
    g.span_lo = g.active_lo;
    g.span_hi = g.active_hi;
    return;
  }
  const std::size_t lines = g.lines();
  const std::size_t n = st.width > 0 ? st.node.size() / static_cast<std::size_t>(st.width) : 0;
  // Every stencil is a box of the same widths W (clamped into the storage); its first
  // entry is the box's lowest node. Mark those, in storage (ghosts included)...
  std::vector<std::uint8_t>& mark = g.box_marks;
  mark.assign(g.storage, 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t q = 0; q < n; ++q)
    std::atomic_ref<std::uint8_t>(mark[static_cast<std::size_t>(st.node[q * st.width])]).store(1, std::memory_order_relaxed);
  // ...find, per storage line, the lowest and highest first node along x...
  std::array<int, Dim> ns;  // storage nodes per axis
  for (int a = 0; a < Dim; ++a) ns[a] = g.cells[a] + 1 + 2 * Grid<Dim>::ghost;
  const std::size_t storage_lines = g.storage / static_cast<std::size_t>(ns[0]);
  std::vector<int> first_lo(storage_lines, INT_MAX), first_hi(storage_lines, INT_MIN);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t l = 0; l < storage_lines; ++l) {
    const std::uint8_t* m = &mark[l * static_cast<std::size_t>(ns[0])];
    int lo = 0, hi = ns[0] - 1;
    while (lo < ns[0] && !m[lo]) ++lo;
    if (lo == ns[0]) continue;
    while (!m[hi]) --hi;
    first_lo[l] = lo, first_hi[l] = hi;
  }
  // ...and give each real line the x-range of the boxes over it, one node wider on
  // every side: from the storage lines W - 1 below it to one below, to one above.
  std::array<int, Dim> W = st.box;
  std::vector<int> lo(lines, INT_MAX), hi(lines, INT_MIN);
  for (std::size_t l = 0; l < lines; ++l) {
    const auto idx = g.line_first(l);
    const int sy = idx[1] + Grid<Dim>::ghost, sz = Dim == 3 ? idx[Dim - 1] + Grid<Dim>::ghost : 0;
    const int z0 = Dim == 3 ? std::max(sz - W[Dim - 1], 0) : 0, z1 = Dim == 3 ? std::min(sz + 1, ns[Dim - 1] - 1) : 0;
    const int y0 = std::max(sy - W[1], 0), y1 = std::min(sy + 1, ns[1] - 1);
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y) {
        const std::size_t m = static_cast<std::size_t>(y) + static_cast<std::size_t>(ns[1]) * static_cast<std::size_t>(z);
        if (first_lo[m] > first_hi[m]) continue;
        lo[l] = std::min(lo[l], first_lo[m] - Grid<Dim>::ghost - 1);
        hi[l] = std::max(hi[l], first_hi[m] - Grid<Dim>::ghost + W[0]);
      }
    if (lo[l] <= hi[l]) lo[l] = std::max(lo[l], 0), hi[l] = std::min(hi[l], g.cells[0]);
  }
  // An empty range is (INT_MAX, INT_MIN), so the union of two is their min and max.
  g.span_lo.resize(lines);
  g.span_hi.resize(lines);
  for (std::size_t l = 0; l < lines; ++l) {
    g.span_lo[l] = std::min(g.active_lo[l], lo[l]);
    g.span_hi[l] = std::max(g.active_hi[l], hi[l]);
  }
  g.active_lo.swap(lo);
  g.active_hi.swap(hi);
}

template <int Dim>
void clear_active(Grid<Dim>& g, int threads) {
  for_each_range(g, g.active_lo, g.active_hi, threads, [&g](std::size_t, std::size_t i0, int lo, int hi) {
    for (std::size_t i = i0 + static_cast<std::size_t>(lo); i <= i0 + static_cast<std::size_t>(hi); ++i) {
      g.mass[i] = 0.0;
      for (int d = 0; d < Dim; ++d) g.momentum[d][i] = g.force[d][i] = 0.0;
    }
  });
}

template void mark_active_lines<2>(Grid<2>&, const Stencil<2>&, int);
template void mark_active_lines<3>(Grid<3>&, const Stencil<3>&, int);
template void clear_active<2>(Grid<2>&, int);
template void clear_active<3>(Grid<3>&, int);

}  // namespace mpmx::mpm
