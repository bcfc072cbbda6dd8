#pragma once
// What every scheme's stencil evaluation shares (scheme.cpp runs the passes; each
// scheme's file fills one particle's entries): the particle's position in cell units,
// its corners or sub-points placed by its domain vectors, the box of entries (x fastest)
// and its nodes, and the tensor products of 1-D factors.
#include <array>
#include <vector>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/shape/axis.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/scheme.hpp"

namespace mpmx::mpm::shape {

// How far a scheme's entries reach, for the first pass that sizes the box.
enum class Reach {
  hat,     // the 2^d nodes of the particle's cell
  domain,  // the nodes the particle's domain overlaps (GIMP)
  points,  // the cells of its corners (CPDI) or sub-points
};

template <int Dim>
struct StencilBuild {
  const Grid<Dim>& g;
  const Particles<Dim>& p;
  const SchemeOptions& opt;
  bool corners;                                 // CPDI's deformed domains (2-D, 3-D)
  std::array<int, Dim> nsub;                    // sub-points per axis (1 but for sub-points)
  int points = 1;                               // corners or sub-points per particle
  std::vector<std::array<double, Dim>> unit;    // u_b of each, once per step
  std::array<int, Dim> W{};                     // the box's widths
  int width = 1;                                // entries per particle
  std::array<int, 1 << Dim> hat_step{};         // a hat's nodes after its first

  StencilBuild(const Grid<Dim>& grid, const Particles<Dim>& parts, const SchemeOptions& o, bool corner_points,
               bool subpoints)
      : g(grid), p(parts), opt(o), corners(corner_points) {
    for (int d = 0; d < Dim; ++d) nsub[d] = !subpoints ? 1 : Dim == 1 ? o.subpoints : o.subpoints_axes[d];
    for (int d = 0; d < Dim; ++d) points *= corners ? 2 : nsub[d];
    // Position of corner or sub-point `c` from the domain vectors: x + sum_b r_b u_b with
    // u_b = s_b / 2 (corners) or (s_b + 1/2) / n - 1/2.
    unit.resize(points);
    for (int c = 0; c < points; ++c)
      for (int b = 0, rest = c; b < Dim; ++b) {
        const int s = corners ? c >> b & 1 : rest % nsub[b];
        rest /= nsub[b];
        unit[c][b] = corners ? (s ? 0.5 : -0.5) : (s + 0.5) / nsub[b] - 0.5;
      }
    for (int k = 0; k < (1 << Dim); ++k)
      for (int a = 0; a < Dim; ++a) hat_step[k] += (k >> a & 1) * g.stride[a];
  }

  // Half the particle's domain along axis d, in cells.
  double half(std::size_t q, int d) const { return 0.5 * p.length[d * Dim + d][q] * g.inv_dx[d]; }

  std::array<double, Dim> cell_units(std::size_t q) const {
    std::array<double, Dim> xi;
    for (int d = 0; d < Dim; ++d) xi[d] = (p.x[d][q] - g.lower[d]) * g.inv_dx[d];
    return xi;
  }

  // Corner or sub-point c of particle q (at xi), in cell units.
  std::array<double, Dim> place(std::size_t q, const std::array<double, Dim>& xi, int c) const {
    std::array<double, Dim> at = xi;
    const std::array<double, Dim>& u = unit[c];
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) at[a] += p.length[a * Dim + b][q] * g.inv_dx[a] * u[b];
    return at;
  }

  // The nodes of a hat's box (mpm, ddmp), which never reaches past the grid: the first
  // node plus a fixed step per entry.
  void hat_nodes(const Axis* ax, int* node) const {
    std::array<int, Dim> first;
    for (int d = 0; d < Dim; ++d) first[d] = ax[d].first;
    const int base = static_cast<int>(g.index(first));
    for (int k = 0; k < (1 << Dim); ++k) node[k] = base + hat_step[k];
  }
};

// The offsets of the entry after o in a stencil box of widths W, x fastest (an odometer:
// no division per entry, which in the wide boxes of sub-points took a good part of the step).
template <int Dim>
inline void next_entry(std::array<int, Dim>& o, const std::array<int, Dim>& W) {
  for (int a = 0; a < Dim && ++o[a] == W[a]; ++a) o[a] = 0;
}

// The stencil's node indices for the box starting at ax[d].first.
template <int Dim>
inline void set_nodes(const Grid<Dim>& g, const Axis* ax, const std::array<int, Dim>& W, int width, int* node) {
  std::array<int, Dim> o{};
  for (int k = 0; k < width; ++k, next_entry<Dim>(o, W)) {
    std::array<int, Dim> idx;
    for (int d = 0; d < Dim; ++d) idx[d] = ax[d].first + o[d];
    node[k] = static_cast<int>(g.index_clamped(idx));
  }
}

// S = prod_a S_a, G_d = S_d' prod_{a != d} S_a: the tensor product of 1-D factors,
// entries x fastest.
template <int Dim>
inline void separable(const Axis* ax, const std::array<int, Dim>& W, int width, double* S, std::array<double*, Dim> G) {
  std::array<int, Dim> o{};
  for (int k = 0; k < width; ++k) {
    double s = 1.0;
    for (int a = 0; a < Dim; ++a) s *= ax[a].S[o[a]];
    S[k] = s;
    for (int d = 0; d < Dim; ++d) {
      double gd = ax[d].G[o[d]];
      for (int a = 0; a < Dim; ++a)
        if (a != d) gd *= ax[a].S[o[a]];
      G[d][k] = gd;
    }
    next_entry<Dim>(o, W);
  }
}

// Eq. 7.2 at one evaluation point of weight w, factored (particles.hpp, Stencil): on
// the 2^d hat nodes at box offsets `at`, G_d += w alpha dS_d prod S and R += w (1 - alpha)
// prod S; the smoothed part is the grid's operator applied to R (ddmp_operator.hpp).
template <int Dim>
inline void add_ddmp(const Axis* ax, const std::array<int, Dim>& at, double w, const std::array<int, Dim>& W,
                     DdmpAlpha form, std::array<double*, Dim> G, double* R) {
  double q[Dim];
  for (int a = 0; a < Dim; ++a) q[a] = ax[a].q;
  const double alpha = form == DdmpAlpha::eq_7_3 ? ddmp_alpha_nd<Dim>(q) : ddmp_alpha_product<Dim>(q);
  const double sharp = w * alpha, smooth = w * (1.0 - alpha);
  for (int k = 0; k < (1 << Dim); ++k) {
    std::array<int, Dim> o;
    int flat = 0, stride = 1;
    for (int a = 0; a < Dim; ++a) {
      o[a] = at[a] + (k >> a & 1);
      flat += o[a] * stride;
      stride *= W[a];
    }
    double s = 1.0;
    for (int a = 0; a < Dim; ++a) s *= ax[a].S[o[a]];
    R[flat] += smooth * s;
    for (int d = 0; d < Dim; ++d) {
      double g = ax[d].G[o[d]];
      for (int a = 0; a < Dim; ++a)
        if (a != d) g *= ax[a].S[o[a]];
      G[d][flat] += sharp * g;
    }
  }
}

// One particle's entries as a scheme fills them.
template <int Dim>
struct Entries {
  double* S;
  std::array<double*, Dim> G;
  double* R;   // DDMP's smoothed part (factored schemes)
  int* node;
};

}  // namespace mpmx::mpm::shape
