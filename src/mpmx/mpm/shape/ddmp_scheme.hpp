#pragma once
// DDMP (dissertation eqs. 3.31, 7.2): S_ip the hat at the particle, its gradient the
// blend alpha dS + (1 - alpha) of the grid's smoothed gradient, factored so that the
// smoothed part is the grid's operator applied to R (ddmp_operator.hpp).
#include <string_view>

#include "mpmx/mpm/shape/stencil_build.hpp"

namespace mpmx::mpm::shape {

struct DdmpScheme {
  static constexpr std::string_view name = "ddmp";
  static constexpr bool tracks_domain = false, ddmp = true, subpoints = false;
  template <int Dim>
  static constexpr Reach reach() { return Reach::hat; }
  static constexpr bool adds = true;
  static constexpr bool own_nodes = true;

  template <int Dim>
  static void fill(const StencilBuild<Dim>& b, std::size_t, const std::array<double, Dim>& xi, Axis* ax,
                   const Entries<Dim>& e) {
    const auto& g = b.g;
    for (int d = 0; d < Dim; ++d) ddmp_axis(xi[d], g.cells[d], g.inv_dx[d], 0, ax[d]);
    for (int k = 0; k < b.width; ++k) {
      double s = 1.0;
      for (int a = 0; a < Dim; ++a) s *= ax[a].S[k >> a & 1];
      e.S[k] = s;
    }
    add_ddmp<Dim>(ax, std::array<int, Dim>{}, 1.0, b.W, b.opt.alpha, e.G, e.R);
    b.hat_nodes(ax, e.node);
  }
};

}  // namespace mpmx::mpm::shape
