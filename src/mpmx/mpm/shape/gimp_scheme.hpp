#pragma once
// GIMP (dissertation sec. 3.2): the hat averaged over the particle's domain, an
// axis-aligned box of half-width l / 2 per axis. uGIMP keeps the domain's initial size;
// cpGIMP stretches it with the deformation (tracks_domain).
#include <string_view>

#include "mpmx/mpm/shape/stencil_build.hpp"

namespace mpmx::mpm::shape {

// The domain's factors along each axis and their tensor product; `integrate`: the GIMP
// average (false: CPDI's 1-D corner mean).
template <int Dim>
inline void fill_domain(const StencilBuild<Dim>& b, std::size_t q, const std::array<double, Dim>& xi, Axis* ax,
                        const Entries<Dim>& e, bool integrate) {
  for (int d = 0; d < Dim; ++d) {
    ax[d].clear(b.W[d]);
    domain_axis(xi[d], b.half(q, d), b.g.cells[d], b.g.inv_dx[d], integrate, b.W[d], ax[d]);
  }
  separable<Dim>(ax, b.W, b.width, e.S, e.G);
}

template <bool Tracks>
struct GimpScheme {
  static constexpr std::string_view name = Tracks ? "cpgimp" : "ugimp";
  static constexpr bool tracks_domain = Tracks, ddmp = false, subpoints = false;
  template <int Dim>
  static constexpr Reach reach() { return Reach::domain; }
  static constexpr bool adds = true;
  static constexpr bool own_nodes = false;

  template <int Dim>
  static void fill(const StencilBuild<Dim>& b, std::size_t q, const std::array<double, Dim>& xi, Axis* ax,
                   const Entries<Dim>& e) {
    fill_domain<Dim>(b, q, xi, ax, e, true);
  }
};

using UgimpScheme = GimpScheme<false>;
using CpgimpScheme = GimpScheme<true>;

}  // namespace mpmx::mpm::shape
