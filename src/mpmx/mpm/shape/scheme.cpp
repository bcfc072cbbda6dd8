#include "mpmx/mpm/shape/scheme.hpp"

#include <algorithm>
#include <type_traits>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"
#include "mpmx/mpm/shape/schemes.hpp"

namespace mpmx::mpm {

const std::vector<SchemeInfo>& schemes() {
  static const std::vector<SchemeInfo> s = [] {
    std::vector<SchemeInfo> all;
    shape::Schemes::each([&]<class E>() {
      all.push_back({static_cast<Scheme>(all.size()), std::string(E::name), E::tracks_domain, E::ddmp, E::subpoints});
    });
    return all;
  }();
  return s;
}

const SchemeInfo& scheme_info(Scheme s) { return schemes()[static_cast<std::size_t>(s)]; }

std::vector<std::string> scheme_names() {
  std::vector<std::string> n;
  for (const auto& s : schemes()) n.push_back(s.name);
  return n;
}

Scheme scheme_from_name(std::string_view name) {
  if (shape::Schemes::has(name)) return static_cast<Scheme>(shape::Schemes::index(name));
  throw InputError(fmt::format("unknown scheme '{}' (one of {})", name, fmt::join(scheme_names(), ", ")));
}

std::string scheme_name(Scheme s) { return scheme_info(s).name; }

template <int Dim>
ShapeEvaluator<Dim>::ShapeEvaluator(SchemeOptions opt, const Grid<Dim>& grid) : opt_(opt) {
  if (scheme_info(opt_.scheme).ddmp) {
    ddmp_ = std::make_shared<std::vector<shape::DdmpTable>>();
    for (int d = 0; d < Dim; ++d) ddmp_->emplace_back(grid.cells[d], grid.dx[d]);
  }
}
template <int Dim>
ShapeEvaluator<Dim>::~ShapeEvaluator() = default;
template <int Dim>
ShapeEvaluator<Dim>::ShapeEvaluator(ShapeEvaluator&&) noexcept = default;

namespace {

using shape::Axis;
using shape::Reach;

// Pass 1: every point on the grid (or a cell past it: the first one that is not is
// named), and the box width along each axis, the widest particle's. A minimum and
// maxima: the same for any thread count.
template <class S, int Dim>
void size_box(shape::StencilBuild<Dim>& b, int threads) {
  const auto& g = b.g;
  const std::size_t n = b.p.size();
  std::size_t off_grid = n;
  int widest[Dim];
  std::fill_n(widest, Dim, 2);
#pragma omp parallel for schedule(static) reduction(min : off_grid) reduction(max : widest) num_threads(threads) if (threads > 1)
  for (std::size_t q = 0; q < n; ++q) {
    const std::array<double, Dim> xi = b.cell_units(q);
    bool inside = true;
    for (int d = 0; d < Dim; ++d) inside = inside && shape::within_reach(xi[d], g.cells[d]);
    if (!inside) {
      off_grid = std::min(off_grid, q);
      continue;
    }
    if constexpr (S::template reach<Dim>() == Reach::domain) {
      for (int d = 0; d < Dim; ++d) widest[d] = std::max(widest[d], shape::domain_width(xi[d], b.half(q, d), g.cells[d]));
    } else if constexpr (S::template reach<Dim>() == Reach::points) {
      std::array<int, Dim> lo, hi;
      lo.fill(1 << 30);
      hi.fill(-(1 << 30));
      for (int c = 0; c < b.points; ++c) {
        const auto at = b.place(q, xi, c);
        for (int d = 0; d < Dim; ++d) {
          const int cell = shape::ddmp_cell(at[d], g.cells[d]);
          lo[d] = std::min(lo[d], cell);
          hi[d] = std::max(hi[d], cell + 1);
        }
      }
      for (int d = 0; d < Dim; ++d) widest[d] = std::max(widest[d], hi[d] - lo[d] + 1);
    }
  }
  if (off_grid < n)  // throws with its number and position
    for (int d = 0; d < Dim; ++d)
      shape::require_inside((b.p.x[d][off_grid] - g.lower[d]) * g.inv_dx[d], g.cells[d], off_grid, b.p.x[d][off_grid],
                            d);
  b.width = 1;
  for (int d = 0; d < Dim; ++d) {
    b.W[d] = widest[d];
    shape::require_width(b.W[d]);
    b.width *= b.W[d];
  }
}

// Pass 2: every particle's factors and their products, each particle on its own.
template <class S, int Dim>
void fill_all(const shape::StencilBuild<Dim>& b, Stencil<Dim>& st, int threads) {
  const std::size_t n = b.p.size();
  const int width = b.width;
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t q = 0; q < n; ++q) {
    Axis ax[Dim];
    const std::array<double, Dim> xi = b.cell_units(q);
    const std::size_t e = q * static_cast<std::size_t>(width);
    shape::Entries<Dim> entries{&st.S[e], {}, S::ddmp ? &st.R[e] : nullptr, &st.node[e]};
    for (int d = 0; d < Dim; ++d) entries.G[d] = &st.G[d][e];
    if constexpr (S::adds) {  // these schemes add into their entries
      std::fill(entries.S, entries.S + width, 0.0);
      for (int d = 0; d < Dim; ++d) std::fill(entries.G[d], entries.G[d] + width, 0.0);
      if constexpr (S::ddmp) std::fill(entries.R, entries.R + width, 0.0);
    }
    S::template fill<Dim>(b, q, xi, ax, entries);
    if constexpr (!S::own_nodes) shape::set_nodes<Dim>(b.g, ax, b.W, width, entries.node);
  }
}

}  // namespace

// The scheme chosen once per call: its passes instantiated for it (no per-particle branch).
template <int Dim>
void ShapeEvaluator<Dim>::operator()(const Grid<Dim>& g, const Particles<Dim>& p, Stencil<Dim>& st) const {
  shape::Schemes::at(static_cast<std::size_t>(opt_.scheme), [&]<class S>() {
    shape::StencilBuild<Dim> b(g, p, opt_, std::is_same_v<S, shape::CpdiScheme> && Dim > 1, S::subpoints);
    size_box<S>(b, threads_);
    st.reset(p.size(), b.width, false, S::ddmp);  // each particle's entries are cleared by its thread below
    st.box = b.W;
    if constexpr (S::ddmp) st.smooth = ddmp_;
    fill_all<S>(b, st, threads_);
    if constexpr (S::ddmp) shape::mark_smoothing_nodes(g, st, mark_, threads_);
  });
}

template class ShapeEvaluator<1>;
template class ShapeEvaluator<2>;
template class ShapeEvaluator<3>;

}  // namespace mpmx::mpm
