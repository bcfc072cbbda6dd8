#pragma once
// A uniform background grid in Dim dimensions with node fields stored as arrays
// (structure-of-arrays). Node storage carries one ghost layer on each side so that
// the wide DDMP stencils (nodes c-1 .. c+2 of cell c) never need a bounds test; the
// ghost nodes never carry mass, force or velocity.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mpmx::mpm {

// The weights of v^L and v^n in the velocities x and grad v are advanced with:
// v^{n+1/2} = (v^L + v^n) / 2 (eqs. 3.14, 4.10) or v^L alone.
struct VelocityWeights {
  double L, n;
};
inline VelocityWeights midpoint_weights(bool midpoint) { return midpoint ? VelocityWeights{0.5, 0.5} : VelocityWeights{1.0, 0.0}; }

template <int Dim>
struct Grid {
  static constexpr int ghost = 1;
  static constexpr int dim = Dim;

  std::array<double, Dim> lower{};
  std::array<double, Dim> upper{};
  // The corners at t = 0, where a piston carries the grid from (piston_grid.hpp);
  // lower and upper otherwise.
  std::array<double, Dim> rest_lower{};
  std::array<double, Dim> rest_upper{};
  std::array<int, Dim> cells{};
  std::array<double, Dim> dx{};
  std::array<double, Dim> inv_dx{};
  std::array<int, Dim> stride{};  // storage stride per dimension (with ghosts)
  std::size_t storage = 0;        // nodes incl. ghosts

  // Node fields (size `storage`).
  std::vector<double> mass;
  std::array<std::vector<double>, Dim> momentum;  // re-used as velocity v^n after the solve
  std::array<std::vector<double>, Dim> velocity;  // v^n
  std::array<std::vector<double>, Dim> velocity_L;  // Lagrangian v^L (eq. 3.12)
  std::array<std::vector<double>, Dim> force;       // internal force (eq. 3.9/3.30)
  // The velocities the velocity gradient reads where the small-mass distribution is on
  // (eq. 7.7, mass_distribution.hpp): w_L v^L + w_n v^n (midpoint_weights) through the
  // distribution's adjoint; empty otherwise.
  std::array<std::vector<double>, Dim> gradient_velocity;
  // DDMP's smoothed part on the nodes (shape/ddmp_operator.hpp), [a * Dim + d], empty
  // unless the scheme is DDMP: T_j = sum_p V_p sigma_p S_j (1 - alpha_p), zero between
  // steps, and the smoothed velocity gradient H_j = sum_i K_ji v_i.
  std::array<std::vector<double>, Dim * Dim> smooth_stress, smooth_gradient;
  // Per node line along x (active_lines.hpp): the x-ranges [lo, hi] of the nodes this
  // step works on (`active`; empty where lo > hi) and those with the last step's
  // (`span`). The whole grid until a 2-D or 3-D step has marked them (1-D: always).
  // Nodes outside keep zero mass, momentum and force; their velocities are not read (a
  // face's prescribed velocity there is that of the last step that reached them).
  std::vector<int> active_lo, active_hi, span_lo, span_hi;
  std::vector<std::uint8_t> box_marks;  // scratch of active_lines.cpp

  Grid() = default;
  Grid(std::array<double, Dim> lo, std::array<double, Dim> hi, std::array<int, Dim> n)
      : lower(lo), upper(hi), rest_lower(lo), rest_upper(hi), cells(n) {
    std::size_t s = 1;
    for (int d = 0; d < Dim; ++d) {
      dx[d] = (hi[d] - lo[d]) / n[d];
      inv_dx[d] = 1.0 / dx[d];
      stride[d] = static_cast<int>(s);
      s *= static_cast<std::size_t>(n[d] + 1 + 2 * ghost);
    }
    storage = s;
    mass.assign(storage, 0.0);
    for (int d = 0; d < Dim; ++d) {
      momentum[d].assign(storage, 0.0);
      velocity[d].assign(storage, 0.0);
      velocity_L[d].assign(storage, 0.0);
      force[d].assign(storage, 0.0);
    }
    active_lo.assign(lines(), 0);
    active_hi.assign(lines(), cells[0]);
    span_lo = active_lo;
    span_hi = active_hi;
  }

  int nodes(int d) const { return cells[d] + 1; }
  // Lines of real nodes along x: the unit threads take in passes over the grid.
  std::size_t lines() const {
    std::size_t n = 1;
    for (int d = 1; d < Dim; ++d) n *= static_cast<std::size_t>(cells[d] + 1);
    return n;
  }
  // Grid indices of line l's first node (x = 0), lines counted y fastest.
  std::array<int, Dim> line_first(std::size_t l) const {
    std::array<int, Dim> idx{};
    for (int d = 1; d < Dim; ++d) {
      idx[d] = static_cast<int>(l % static_cast<std::size_t>(cells[d] + 1));
      l /= static_cast<std::size_t>(cells[d] + 1);
    }
    return idx;
  }
  // Storage index of the node with grid indices idx (each in [-ghost, cells+ghost]).
  std::size_t index(std::array<int, Dim> idx) const {
    std::size_t s = 0;
    for (int d = 0; d < Dim; ++d) s += static_cast<std::size_t>(idx[d] + ghost) * stride[d];
    return s;
  }
  // Storage index of node i along x in 1-D.
  std::size_t index1(int i) const { return static_cast<std::size_t>(i + ghost); }
  double node_x(int i, int d = 0) const { return lower[d] + i * dx[d]; }
  // Storage index with each grid index clamped into the stored range.
  std::size_t index_clamped(std::array<int, Dim> idx) const {
    for (int d = 0; d < Dim; ++d) idx[d] = idx[d] < -ghost ? -ghost : idx[d] > cells[d] + ghost ? cells[d] + ghost : idx[d];
    return index(idx);
  }
  // Whether grid indices idx name a real (non-ghost) node.
  bool real(const std::array<int, Dim>& idx) const {
    for (int d = 0; d < Dim; ++d)
      if (idx[d] < 0 || idx[d] > cells[d]) return false;
    return true;
  }
  // Calls f(storage index, grid indices) for every real node, x fastest.
  template <class F>
  void for_each_node(F&& f) const {
    std::array<int, Dim> idx{};
    while (true) {
      f(index(idx), idx);
      int d = 0;
      while (d < Dim && ++idx[d] > cells[d]) idx[d++] = 0;
      if (d == Dim) return;
    }
  }
  // Volume of the grid cell (V_j of eq. 3.28 for interior nodes).
  double cell_volume() const {
    double v = 1.0;
    for (int d = 0; d < Dim; ++d) v *= dx[d];
    return v;
  }
};

}  // namespace mpmx::mpm
