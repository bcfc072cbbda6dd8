#pragma once
// The nodal solve: Lagrangian velocity v^L = v^n + dt f/m (eqs. 3.10, 3.12) with the
// boundary nodes held to their prescribed velocity, and the per-step conservation
// tallies (boundary impulse and work, force balance eq. 4.7, nodal mass).
#include "mpmx/mpm/state.hpp"

namespace mpmx::mpm {

// Threads over lines of nodes (2-D, 3-D); the same bits for any count.
template <int Dim>
void solve_grid(Grid<Dim>& g, const Boundaries& bc, double t, double dt, Tallies& tally, int threads = 1);

// W += dt sum_p V_p (sigma_p - q_p) : grad v_p (the energy the stress absorbs, eq. 4.11,
// over V0 for small strain), then V^{n+1} = V^n (1 + dt div v) and, when the scheme
// tracks it, the domain vectors by dr/dt = grad v r.
template <int Dim>
void work_and_volumes(Particles<Dim>& p, double dt, bool small_strain, bool track_domain, Tallies& tally,
                      int threads = 1);

}  // namespace mpmx::mpm
