#pragma once
// The original MPM (dissertation sec. 3.1): the hat functions of the particle's cell,
// S_ip = prod_a N_a(x_a), and their gradient (eq. 3.9).
#include <string_view>

#include "mpmx/mpm/shape/stencil_build.hpp"

namespace mpmx::mpm::shape {

struct MpmScheme {
  static constexpr std::string_view name = "mpm";
  static constexpr bool tracks_domain = false, ddmp = false, subpoints = false;
  template <int Dim>
  static constexpr Reach reach() { return Reach::hat; }
  static constexpr bool adds = false;       // writes every entry (no clearing first)
  static constexpr bool own_nodes = true;   // sets its nodes itself

  template <int Dim>
  static void fill(const StencilBuild<Dim>& b, std::size_t, const std::array<double, Dim>& xi, Axis* ax,
                   const Entries<Dim>& e) {
    const auto& g = b.g;
    // The products unrolled (the same, in the same order, as separable()).
    for (int d = 0; d < Dim; ++d) hat_axis(xi[d], g.cells[d], g.inv_dx[d], ax[d]);
    for (int k = 0; k < (1 << Dim); ++k) {
      double sk = 1.0;
      for (int a = 0; a < Dim; ++a) sk *= ax[a].S[k >> a & 1];
      e.S[k] = sk;
      for (int d = 0; d < Dim; ++d) {
        double gd = ax[d].G[k >> d & 1];
        for (int a = 0; a < Dim; ++a)
          if (a != d) gd *= ax[a].S[k >> a & 1];
        e.G[d][k] = gd;
      }
    }
    b.hat_nodes(ax, e.node);
  }
};

}  // namespace mpmx::mpm::shape
