#pragma once
// CPDI (Sadeghirad et al.; dissertation sec. 3.3): in 2-D and 3-D the particle's domain
// is the parallelogram (parallelepiped) of its domain vectors, S_ip the mean of the
// corner values and grad S_ip the mean gradient of their multilinear interpolant over
// it, 2 R^-T g with g_b = sum_c s_b S(x_c) / 2^d and R the domain vectors as columns. In
// 1-D, the mean of the two ends' hats over the tracked length.
#include <string_view>
#include <vector>

#include "mpmx/mpm/shape/gimp_scheme.hpp"
#include "mpmx/mpm/shape/stencil_build.hpp"

namespace mpmx::mpm::shape {

struct CpdiScheme {
  static constexpr std::string_view name = "cpdi";
  static constexpr bool tracks_domain = true, ddmp = false, subpoints = false;
  template <int Dim>
  static constexpr Reach reach() { return Dim == 1 ? Reach::domain : Reach::points; }
  static constexpr bool adds = true;
  static constexpr bool own_nodes = false;

  template <int Dim>
  static void fill(const StencilBuild<Dim>& b, std::size_t q, const std::array<double, Dim>& xi, Axis* ax,
                   const Entries<Dim>& e) {
    if constexpr (Dim == 1) fill_domain<Dim>(b, q, xi, ax, e, false);
    else fill_corners<Dim>(b, q, xi, ax, e);
  }

 private:
  template <int Dim>
  static void fill_corners(const StencilBuild<Dim>& b, std::size_t q, const std::array<double, Dim>& xi, Axis* ax,
                           const Entries<Dim>& e) {
    const auto& g = b.g;
    const int width = b.width, points = b.points;
    std::array<int, Dim> lo;
    lo.fill(1 << 30);
    for (int c = 0; c < points; ++c) {
      const auto at = b.place(q, xi, c);
      for (int d = 0; d < Dim; ++d) lo[d] = std::min(lo[d], ddmp_cell(at[d], g.cells[d]));
    }
    for (int d = 0; d < Dim; ++d) ax[d].first = lo[d];
    std::array<std::vector<double>, Dim> gxi;
    for (auto& v : gxi) v.assign(width, 0.0);
    for (int c = 0; c < points; ++c) {
      const auto at = b.place(q, xi, c);
      Axis cx[Dim];
      for (int d = 0; d < Dim; ++d) {
        cx[d].clear(b.W[d]);
        const int cell = ddmp_cell(at[d], g.cells[d]);
        for (int k = 0; k < 2; ++k) {
          const int i = cell + k;
          cx[d].S[cell - lo[d] + k] = hat_ext(at[d], i, g.cells[d]);
        }
      }
      std::array<int, Dim> o{};
      for (int k = 0; k < width; ++k, next_entry<Dim>(o, b.W)) {
        double s = 1.0;
        for (int a = 0; a < Dim; ++a) s *= cx[a].S[o[a]];
        e.S[k] += s / points;
        for (int bb = 0; bb < Dim; ++bb) gxi[bb][k] += ((c >> bb & 1) ? s : -s) / points;
      }
    }
    // R^-T by the cofactors of R (2-D, 3-D).
    double R[3][3] = {}, inv[3][3] = {};
    for (int a = 0; a < Dim; ++a)
      for (int bb = 0; bb < Dim; ++bb) R[a][bb] = b.p.length[a * Dim + bb][q];
    if constexpr (Dim == 2) {
      const double det = R[0][0] * R[1][1] - R[0][1] * R[1][0];
      inv[0][0] = R[1][1] / det, inv[0][1] = -R[0][1] / det;
      inv[1][0] = -R[1][0] / det, inv[1][1] = R[0][0] / det;
    } else if constexpr (Dim == 3) {
      const double det = R[0][0] * (R[1][1] * R[2][2] - R[1][2] * R[2][1]) -
                         R[0][1] * (R[1][0] * R[2][2] - R[1][2] * R[2][0]) +
                         R[0][2] * (R[1][0] * R[2][1] - R[1][1] * R[2][0]);
      for (int a = 0; a < 3; ++a)
        for (int bb = 0; bb < 3; ++bb) {
          const int a1 = (bb + 1) % 3, a2 = (bb + 2) % 3, b1 = (a + 1) % 3, b2 = (a + 2) % 3;
          inv[a][bb] = (R[a1][b1] * R[a2][b2] - R[a1][b2] * R[a2][b1]) / det;  // (R^-1)_ab
        }
    }
    for (int k = 0; k < width; ++k)
      for (int d = 0; d < Dim; ++d) {
        double v = 0.0;
        for (int bb = 0; bb < Dim; ++bb) v += inv[bb][d] * gxi[bb][k];  // (R^-T)_db = (R^-1)_bd
        e.G[d][k] = 2.0 * v;
      }
  }
};

}  // namespace mpmx::mpm::shape
