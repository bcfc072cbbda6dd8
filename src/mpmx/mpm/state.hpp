#pragma once
// Everything one continuum run advances: grid, particles, the step's stencil, the
// scheme and material chosen once, boundaries, and running conservation tallies.
#include <array>
#include <cstdint>
#include <memory>

#include "mpmx/material/material.hpp"
#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/manufactured.hpp"
#include "mpmx/mpm/mass_distribution.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/mpm/phase_times.hpp"
#include "mpmx/mpm/fused1d/linear_fused.hpp"
#include "mpmx/mpm/shape/scheme.hpp"

namespace mpmx::mpm {

// Running sums over the steps taken (S4 of the validation catalog).
struct Tallies {
  std::array<double, 3> boundary_impulse{};  // momentum the boundary nodes added
  double boundary_work = 0.0;      // energy the boundary nodes added
  double body_work = 0.0;          // energy a manufactured solution's body force added (its power on v^n)
  double stress_work = 0.0;        // sum V sigma:grad v dt (eq. 4.11)
  double max_force_sum = 0.0;      // max over steps of |sum_i f_i| / sum_i |f_i|  (eq. 4.7)
  double node_mass = 0.0;          // sum of nodal masses at the last step (eq. 3.11)
};

// The small-mass distribution of eqs. 7.4-7.7: force and momentum of nodes without
// mass (C0) and then of nodes lighter than m_eps (C1) shared among the nodes of their
// cells by sqrt(m).
struct MassDistribution {
  bool on = false;
  double threshold = 0.0;  // m_eps (mass units)
  SmallMassMaps maps;      // this step's
};

// Tensor artificial viscosity, eqs. 7.8-7.10 (off when c_L = c_q = 0).
struct TensorViscosity {
  bool on = false;
  double c_L = 1.5, c_q = 2.0;
};

template <int Dim>
struct State {
  Grid<Dim> grid;
  Particles<Dim> particles;
  Stencil<Dim> stencil;
  shape::LinearCells linear_cells;  // the fused 1-D path keeps only these
  std::unique_ptr<ShapeEvaluator<Dim>> shape;
  std::unique_ptr<material::Material<Dim>> material;
  Boundaries boundary;
  MassDistribution mass_distribution;
  TensorViscosity tensor_viscosity;
  std::shared_ptr<const Manufactured<Dim>> manufactured;  // its body force drives the run (N4)
  bool move = true;
  bool small_strain = false;  // force and work integrals over V0 (ADMPM's geometrically linear form)
  bool midpoint_gradient = true;  // grad v at v^{n+1/2} (eq. 4.10) or at v^L
  bool musl = false;              // grad v from the re-mapped new velocities (mpm/musl.hpp)
  std::array<std::vector<double>, Dim> musl_velocity;  // its nodal velocities
  double viscosity = 0.0;     // linear artificial viscosity coefficient (1-D form, ch. 6)
  double time = 0.0;
  double finite_check = 0.0;  // sum of new v and x of the last step: NaN/Inf shows here
  std::int64_t step = 0;
  int threads = 1;            // over particles (2-D, 3-D); results do not depend on it
  Tallies tallies;
  PhaseTimes phases;  // the stencil step's wall time by phase (this invocation's)
};

}  // namespace mpmx::mpm
