#include "mpmx/app/mpm/xt_diagram.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/app/mpm/output.hpp"
#include "mpmx/app/mpm/time_rows.hpp"

namespace mpmx::app {

template <int Dim>
XtDiagram<Dim>::XtDiagram(const MpmConfig& c, const mpm::Grid<Dim>& g)
    : every_(c.xt_every > 0 ? c.xt_every : std::max<std::int64_t>(1, c.steps() / 400)),
      interval_(c.cfl_dt && c.xt_every == 0 ? c.end / 400.0 : 0.0) {
  header_ = "time";
  // The grid's cells where they were at t = 0: a piston carries the grid (piston_grid.hpp),
  // the table's columns stay where they are.
  for (int j = 0; j < g.cells[0]; ++j) header_ += fmt::format(",{:.10g}", g.rest_lower[0] + (j + 0.5) * g.dx[0]);
  header_ += "\n";
  sum_.assign(g.cells[0], 0.0);
  count_.assign(g.cells[0], 0.0);
}

template <int Dim>
void XtDiagram<Dim>::sample(const mpm::State<Dim>& s, double t_before, Output& out) {
  if (interval_ > 0.0 ? s.step > 0 && !passes_multiple(t_before, s.time, interval_) : s.step % every_ != 0) return;
  const auto& g = s.grid;
  const auto& p = s.particles;
  std::fill(sum_.begin(), sum_.end(), 0.0);
  std::fill(count_.begin(), count_.end(), 0.0);
  const int n = g.cells[0];
  for (std::size_t q = 0; q < p.size(); ++q) {  // in point order: the same sums on any thread count
    const int j = static_cast<int>(std::floor((p.x[0][q] - g.rest_lower[0]) * g.inv_dx[0]));
    if (j < 0 || j >= n) continue;
    sum_[j] += p.stress[0][q];
    count_[j] += 1.0;
  }
  row_.assign(1, s.time);
  for (int j = 0; j < n; ++j) row_.push_back(count_[j] > 0 ? sum_[j] / count_[j] : std::nan(""));
  out.row("xt_sigma_xx.csv", header_, row_);
}

template class XtDiagram<1>;
template class XtDiagram<2>;
template class XtDiagram<3>;

}  // namespace mpmx::app
