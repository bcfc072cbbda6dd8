#pragma once
// One-dimensional factors of the tensor-product schemes: the values along one axis of
// the nodes first .. first + width - 1 that an evaluation point sees. Coordinates are
// in cell units, xi = (x - lower) / dx.
#include <algorithm>
#include <cmath>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/hat.hpp"

namespace mpmx::mpm::shape {

// Widest stencil along one axis (a sub-point lattice or a stretched domain spanning
// more cells stops the run with a message).
inline constexpr int kMaxAxis = 24;

struct Axis {
  int first = 0;
  double S[kMaxAxis];   // shape factor
  double G[kMaxAxis];   // its derivative (per unit length)
  double q = 0.0;       // DDMP: 4 f (1 - f), alpha's factor along the axis (eq. 7.3)

  void clear(int width) {
    std::fill(S, S + width, 0.0);
    std::fill(G, G + width, 0.0);
  }
};

inline void require_width(int width) {
  if (width > kMaxAxis)
    throw RunError("a particle's stencil spans " + std::to_string(width) +
                   " nodes along an axis (at most " + std::to_string(kMaxAxis) +
                   "): its domain has stretched over too many cells");
}

// Original MPM: hat values at xi (continued flat past the ends, with no gradient there).
inline void hat_axis(double xi, int cells, double inv, Axis& a) {
  const double xc = clamp_to_grid(xi, cells);
  const int c = std::min(static_cast<int>(xc), cells - 1);  // xc >= 0: truncation is floor
  const double f = xc - c;
  a.first = c;
  a.S[0] = 1.0 - f;
  a.S[1] = f;
  const double g = (xi >= 0.0 && xi <= cells) ? inv : 0.0;
  a.G[0] = -g;
  a.G[1] = g;
}

// First node of a domain [xi - h, xi + h] (GIMP, 1-D CPDI).
inline int domain_first(double xi, double h, int cells) {
  return static_cast<int>(std::floor(clamp_to_grid(xi - h, cells)));
}
inline int domain_width(double xi, double h, int cells) {
  return static_cast<int>(std::floor(clamp_to_grid(xi + h, cells)) - std::floor(clamp_to_grid(xi - h, cells))) + 2;
}

// GIMP (eqs. 3.17-3.20) when `integrate`: the hat averaged over the domain; CPDI in 1-D
// (eqs. 3.23-3.24) otherwise: the average of its two corner values. Both have the
// gradient (S_i(x_2) - S_i(x_1)) / l_p. Nodes off the grid take no weight.
inline void domain_axis(double xi, double h, int cells, double inv, bool integrate, int width, Axis& ax) {
  const double a = xi - h, b = xi + h;
  ax.first = domain_first(xi, h, cells);
  const double inv_l = 1.0 / (2.0 * h);
  for (int k = 0; k < width; ++k) {
    const int i = ax.first + k;
    if (i < 0 || i > cells) continue;
    const double sa = hat_ext(a, i, cells), sb = hat_ext(b, i, cells);
    ax.S[k] = integrate ? (hat_ext_integral(b, i, cells) - hat_ext_integral(a, i, cells)) * inv_l : 0.5 * (sa + sb);
    ax.G[k] = (sb - sa) * inv_l * inv;
  }
}

// DDMP at xi: the hats of nodes c, c+1 and their derivative, written at offset `at`
// (first = c - at); alpha's factor along the axis. Past the grid ends the point is
// clamped. The smoothed part of eq. 7.2 is the grid's operator (ddmp_operator.hpp).
inline void ddmp_axis(CellPos cp, double inv, int at, Axis& ax) {
  const auto [c, f] = cp;
  ax.first = c - at;
  ax.q = 4.0 * f * (1.0 - f);
  ax.S[at] = 1.0 - f;
  ax.S[at + 1] = f;
  ax.G[at] = -inv;
  ax.G[at + 1] = inv;
}
inline void ddmp_axis(double xi, int cells, double inv, int at, Axis& ax) {
  ddmp_axis(locate(clamp_to_grid(xi, cells), cells), inv, at, ax);
}
inline int ddmp_cell(double xi, int cells) { return locate(clamp_to_grid(xi, cells), cells).cell; }

// alpha of eq. 7.3: 0.5 (prod_k n_c S_k)^(3 / (2 (n_c - 1) d)) over the n_c = 2^d nodes of
// the cell, which on a tensor-product cell is 0.5 prod_a q_a^(2^(d-1) 3 / (2 (2^d - 1) d)).
// In 1-D: 0.5 q^(3/2), eq. 3.27.
template <int Dim>
double ddmp_alpha_nd(const double* q) {
  if constexpr (Dim == 1) return 0.5 * q[0] * std::sqrt(q[0]);
  else if constexpr (Dim == 2) return 0.5 * std::sqrt(q[0] * q[1]);
  else return 0.5 * std::pow(q[0] * q[1] * q[2], 2.0 / 7.0);
}
// The axis-product alternative: 0.5 prod_a q_a^(3/2).
template <int Dim>
double ddmp_alpha_product(const double* q) {
  double a = 0.5;
  for (int d = 0; d < Dim; ++d) a *= q[d] * std::sqrt(q[d]);
  return a;
}

}  // namespace mpmx::mpm::shape
