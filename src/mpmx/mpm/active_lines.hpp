#pragma once
// The part of the grid a 2-D or 3-D step works on. Points fill a fraction of the grid
// (a tenth of it in the two-sphere bench), so the passes over nodes (clearing, the
// small-mass maps, the solve, the gradient velocities) visit, per line of nodes along
// x, the range of nodes the points' stencils hold and one node around them: the reach
// of the small-mass distribution and of DDMP's smoothed force. Nodes outside hold no
// mass, momentum or force, so every sum is what a pass over all nodes gives, bit for
// bit.
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::mpm {

// Grid::active: the ranges of this step's stencils, widened by one node along every
// axis; Grid::span: those with the last step's (where the solve writes, so that a node
// whose points left it gets v = 0). Threads over particles; the ranges are minima and
// maxima, the same for any count.
template <int Dim>
void mark_active_lines(Grid<Dim>& g, const Stencil<Dim>& st, int threads);

// Mass, momentum and force back to zero on the active ranges (all that a step writes).
template <int Dim>
void clear_active(Grid<Dim>& g, int threads);

// Calls f(line, storage index of the line's node x = 0, lo, hi) for every line whose
// range in `lo`/`hi` is not empty; lines on the threads.
template <int Dim, class F>
void for_each_range(const Grid<Dim>& g, const std::vector<int>& lo, const std::vector<int>& hi, int threads, F&& f) {
  const std::size_t lines = g.lines();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (std::size_t l = 0; l < lines; ++l)
    if (lo[l] <= hi[l]) f(l, g.index(g.line_first(l)), lo[l], hi[l]);
}

}  // namespace mpmx::mpm
