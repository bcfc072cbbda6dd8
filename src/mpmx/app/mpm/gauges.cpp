#include "mpmx/app/mpm/gauges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "mpmx/app/mpm/output.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/bcs.hpp"

namespace mpmx::app {

using namespace mpm;

int GaugeTrace::column(const std::string& c) const {
  const auto it = std::find(columns.begin(), columns.end(), c);
  return it == columns.end() ? -1 : static_cast<int>(it - columns.begin());
}

namespace {

constexpr const char* kAxis[] = {"x", "y", "z"};

// The stress components of a point gauge: xx, yy, zz, then the shear ones (2-D: the
// plane-strain sigma_zz as zz).
template <int Dim>
std::vector<std::string> stress_columns() {
  std::vector<std::string> c;
  for (int a = 0; a < Dim; ++a) c.push_back(fmt::format("sigma_{}{}", kAxis[a], kAxis[a]));
  if (Dim == 2) c.push_back("sigma_zz");
  for (int a = 0; a < Dim; ++a)
    for (int b = a + 1; b < Dim; ++b) c.push_back(fmt::format("sigma_{}{}", kAxis[a], kAxis[b]));
  return c;
}

}  // namespace

template <int Dim>
Gauges<Dim>::Gauges(const MpmConfig& c, const State<Dim>& initial, bool keep_rows)
    : gauges_(c.gauges), keep_rows_(keep_rows) {
  if (gauges_.empty()) return;
  const auto& p = initial.particles;
  const std::size_t n = p.size();
  std::vector<int> owner;  // each point's body, in the state's order
  for (const auto& g : gauges_)
    if (g.kind == GaugeConfig::Kind::free_surface && g.body >= 0) {
      owner = placed_points(c).owner;
      break;
    }
  for (const auto& g : gauges_) {
    std::vector<std::size_t> pts;
    GaugeTrace tr;
    tr.name = g.name;
    tr.columns = {"step", "time"};
    if (g.kind == GaugeConfig::Kind::point) {
      // The nearest point (the first of equals: the same on every run of the deck).
      double best = std::numeric_limits<double>::infinity();
      std::size_t at = 0;
      for (std::size_t q = 0; q < n; ++q) {
        double r2 = 0.0;
        for (int d = 0; d < Dim; ++d) r2 += (p.x[d][q] - g.at[d]) * (p.x[d][q] - g.at[d]);
        if (r2 < best) best = r2, at = q;
      }
      pts = {at};
      for (int d = 0; d < Dim; ++d) tr.columns.push_back(kAxis[d]);
      for (int d = 0; d < Dim; ++d) tr.columns.push_back(fmt::format("v{}", kAxis[d]));
      for (const auto& s : stress_columns<Dim>()) tr.columns.push_back(s);
      tr.columns.push_back("density");
    } else {
      // The body's points whose coordinate along the face's axis is within half a point
      // spacing of the body's extreme there (its outermost layer).
      const int axis = g.face / 2;
      const double sign = g.face % 2 == 0 ? -1.0 : 1.0;  // outward along the axis
      const double spacing = initial.grid.dx[axis] / c.per_cell_all[axis];
      auto member = [&](std::size_t q) { return g.body < 0 || owner[q] == g.body; };
      double extreme = -std::numeric_limits<double>::infinity();
      for (std::size_t q = 0; q < n; ++q)
        if (member(q)) extreme = std::max(extreme, sign * p.x[axis][q]);
      for (std::size_t q = 0; q < n; ++q)
        if (member(q) && sign * p.x[axis][q] >= extreme - 0.5 * spacing) pts.push_back(q);
      for (int d = 0; d < Dim; ++d) tr.columns.push_back(kAxis[d]);
      for (int d = 0; d < Dim; ++d) tr.columns.push_back(fmt::format("v{}", kAxis[d]));
      tr.columns.push_back("points");
    }
    std::string header;
    for (std::size_t k = 0; k < tr.columns.size(); ++k) header += (k ? "," : "") + tr.columns[k];
    headers_.push_back(header + "\n");
    points_.push_back(std::move(pts));
    traces_.push_back(std::move(tr));
  }
}

template <int Dim>
void Gauges<Dim>::sample(const State<Dim>& s, Output* out) {
  const auto& p = s.particles;
  for (std::size_t k = 0; k < gauges_.size(); ++k) {
    const GaugeConfig& g = gauges_[k];
    if (s.step % g.every != 0) continue;
    row_.assign({static_cast<double>(s.step), s.time});
    const auto& pts = points_[k];
    if (g.kind == GaugeConfig::Kind::point) {
      const std::size_t q = pts.front();
      for (int d = 0; d < Dim; ++d) row_.push_back(p.x[d][q]);
      for (int d = 0; d < Dim; ++d) row_.push_back(p.v[d][q]);
      for (int a = 0; a < Dim; ++a) row_.push_back(p.stress[a * Dim + a][q]);
      if constexpr (Dim == 2) row_.push_back(p.stress_zz[q]);
      for (int a = 0; a < Dim; ++a)
        for (int b = a + 1; b < Dim; ++b) row_.push_back(p.stress[a * Dim + b][q]);
      row_.push_back(p.density(q));
    } else {
      // The mean over the face's points, summed in their order (any thread count: the same).
      std::array<double, Dim> x{}, v{};
      for (std::size_t q : pts)
        for (int d = 0; d < Dim; ++d) x[d] += p.x[d][q], v[d] += p.v[d][q];
      for (int d = 0; d < Dim; ++d) row_.push_back(x[d] / static_cast<double>(pts.size()));
      for (int d = 0; d < Dim; ++d) row_.push_back(v[d] / static_cast<double>(pts.size()));
      row_.push_back(static_cast<double>(pts.size()));
    }
    if (out) out->row(fmt::format("gauge_{}.csv", g.name), headers_[k], row_);
    if (keep_rows_) traces_[k].rows.push_back(row_);
  }
}

template class Gauges<1>;
template class Gauges<2>;
template class Gauges<3>;

}  // namespace mpmx::app
