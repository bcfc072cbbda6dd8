#pragma once
// DDMP with sub-points (dissertation eqs. 4.5-4.6, 6.1-6.3): S_ip the hat at the
// particle; its gradient eq. 7.2 averaged over sub-points spread evenly in the
// particle's domain (which follows the deformation).
#include <string_view>
#include <vector>

#include "mpmx/mpm/shape/stencil_build.hpp"

namespace mpmx::mpm::shape {

struct DdmpSubpointsScheme {
  static constexpr std::string_view name = "ddmp_subpoints";
  static constexpr bool tracks_domain = true, ddmp = true, subpoints = true;
  template <int Dim>
  static constexpr Reach reach() { return Reach::points; }
  static constexpr bool adds = true;
  static constexpr bool own_nodes = false;

  template <int Dim>
  static void fill(const StencilBuild<Dim>& b, std::size_t q, const std::array<double, Dim>& xi, Axis* ax,
                   const Entries<Dim>& e) {
    const auto& g = b.g;
    const int width = b.width, points = b.points;
    // The box: the cells of the sub-points (the particle's own lies among them); each
    // sub-point located once, kept for the gradient below.
    thread_local std::vector<std::array<CellPos, Dim>> sub;
    sub.resize(static_cast<std::size_t>(points));
    std::array<int, Dim> lo;
    lo.fill(1 << 30);
    for (int c = 0; c < points; ++c) {
      const auto at = b.place(q, xi, c);
      for (int d = 0; d < Dim; ++d) {
        sub[c][d] = locate(clamp_to_grid(at[d], g.cells[d]), g.cells[d]);
        lo[d] = std::min(lo[d], sub[c][d].cell);
      }
    }
    // S: the hat at the particle itself.
    Axis px[Dim];
    for (int d = 0; d < Dim; ++d) {
      px[d].clear(b.W[d]);
      const CellPos own = locate(clamp_to_grid(xi[d], g.cells[d]), g.cells[d]);
      ddmp_axis(own, g.inv_dx[d], own.cell - lo[d], px[d]);
    }
    std::array<int, Dim> o{};
    for (int k = 0; k < width; ++k, next_entry<Dim>(o, b.W)) {
      double s = 1.0;
      for (int a = 0; a < Dim; ++a) s *= px[a].S[o[a]];
      e.S[k] = s;
    }
    // G, R: the volume-weighted mean of eq. 7.2 over the sub-points (eqs. 4.5-4.6).
    const double w = 1.0 / points;
    for (int c = 0; c < points; ++c) {
      std::array<int, Dim> off;
      for (int d = 0; d < Dim; ++d) {
        off[d] = sub[c][d].cell - lo[d];
        ddmp_axis(sub[c][d], g.inv_dx[d], off[d], ax[d]);
      }
      add_ddmp<Dim>(ax, off, w, b.W, b.opt.alpha, e.G, e.R);
    }
    for (int d = 0; d < Dim; ++d) ax[d].first = lo[d];
  }
};

}  // namespace mpmx::mpm::shape
