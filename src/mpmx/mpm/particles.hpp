#pragma once
// Material points in structure-of-arrays form. Tensors are stored by component
// (row-major Dim x Dim), one array each, so loops over particles vectorise.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace mpmx::mpm {

template <int Dim>
struct Particles {
  static constexpr int tensor = Dim * Dim;

  std::size_t size() const { return mass.size(); }

  std::array<std::vector<double>, Dim> x;        // position
  std::array<std::vector<double>, Dim> v;        // velocity
  std::vector<double> mass;
  std::vector<double> volume;                    // current volume, dV/dt = V div v
  std::vector<double> volume0;                   // initial volume
  // Particle domain (GIMP, CPDI, sub-points): edge vector b has components
  // length[a * Dim + b], so it starts as l_b along axis b and follows dr/dt = grad v r.
  // In 1-D length[0] is the domain's length.
  std::array<std::vector<double>, tensor> length;
  std::array<std::vector<double>, tensor> strain;       // integrated strain
  std::array<std::vector<double>, tensor> stress;       // Cauchy stress (tension positive)
  std::vector<double> stress_zz;                 // 2-D: plane strain's sigma_zz (empty otherwise)
  std::array<std::vector<double>, tensor> grad_v;       // velocity gradient at v^{n+1/2} (eq. 4.10)
  std::vector<double> viscous_pressure;          // linear artificial viscosity q (>= 0), ch. 6
  // Tensor artificial viscosity (eqs. 7.8-7.10), added to the stress in the force;
  // empty unless the run uses it.
  std::array<std::vector<double>, tensor> viscous;
  // Labels for the output, which the step never reads: the deck's [[body]] each point was
  // placed from (0 without bodies) and the law it takes (0 the deck's [material], then
  // the bodies' own laws in deck order).
  std::vector<std::int32_t> body, law;

  void resize(std::size_t n) {
    for (int d = 0; d < Dim; ++d) {
      x[d].assign(n, 0.0);
      v[d].assign(n, 0.0);
    }
    mass.assign(n, 0.0);
    volume.assign(n, 0.0);
    volume0.assign(n, 0.0);
    for (int c = 0; c < tensor; ++c) {
      strain[c].assign(n, 0.0);
      stress[c].assign(n, 0.0);
      grad_v[c].assign(n, 0.0);
      length[c].assign(n, 0.0);
    }
    viscous_pressure.assign(n, 0.0);
    body.assign(n, 0);
    law.assign(n, 0);
    if constexpr (Dim == 2) stress_zz.assign(n, 0.0);
  }

  double density(std::size_t p) const { return mass[p] / volume[p]; }
};

namespace shape {
struct DdmpTable;
}

// Per-particle node weights of the current step: node storage index, shape value
// S_ip and (modified) gradient G_ip for `width` entries per particle. Entries past a
// particle's true support carry zero weights, so p2g and g2p are one loop shape for
// every scheme.
//
// DDMP keeps its gradient (eq. 7.2) factored: G holds the sharp part alpha grad S on
// the hat's nodes and R the weights (1 - alpha) S_j of the smoothed part, which is
// sum_j R_j K_ji with K the grid's smoothed-gradient operator (shape/ddmp_operator.hpp).
// The points then see only the hat's 2^d nodes; the smoothing is a pass over the nodes.
template <int Dim>
struct Stencil {
  int width = 0;
  std::array<int, Dim> box{};                // nodes per axis of every particle's box (2-D, 3-D)
  std::vector<int> node;                     // [p * width + k]
  std::vector<double> S;                     // [p * width + k]
  std::array<std::vector<double>, Dim> G;    // [d][p * width + k]
  // DDMP's factored gradient (empty otherwise): R [p * width + k], the operator's
  // factors along each axis, and per storage node whether a point's box holds it
  // ([0, storage)) and whether it lies within one node of such a node ([storage,
  // 2 storage): where the smoothed force lands).
  std::vector<double> R;
  std::shared_ptr<const std::vector<shape::DdmpTable>> smooth;  // one per axis
  std::vector<std::uint8_t> smooth_marks;

  bool smoothed() const { return !R.empty(); }

  // Sizes the arrays; zero-fills them unless the caller writes every entry.
  void reset(std::size_t particles, int w, bool zero = true, bool factored = false) {
    width = w;
    const std::size_t n = particles * static_cast<std::size_t>(w);
    if (zero) {
      node.assign(n, 0);
      S.assign(n, 0.0);
      for (int d = 0; d < Dim; ++d) G[d].assign(n, 0.0);
    } else {
      node.resize(n);
      S.resize(n);
      for (int d = 0; d < Dim; ++d) G[d].resize(n);
    }
    if (!factored) R.clear();
    else if (zero) R.assign(n, 0.0);
    else R.resize(n);
    if (!factored) smooth.reset();
  }
};

}  // namespace mpmx::mpm
