#pragma once
// Leapfrog (eqs. 5.3-5.6) as two free functions over the atom arrays. `threads` > 1
// spreads the atoms of one large system (each atom's update is its own: the same bits
// for any count).
#include <vector>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// v += factor * dt * f / m  (factor 1: eq. 5.3; factor 1/2: eq. 5.4 and the on-step
// velocity of eq. 5.6).
void kick(Atoms& atoms, const std::vector<double>& type_mass, double dt, double factor, int threads = 1);

// x += dt v (eq. 5.5); with `streaming` also the affine motion dt G x of the box.
void drift(Atoms& atoms, double dt, const Mat3& g, bool streaming, int threads = 1);

// Puts every atom into the fundamental box (eq. 5.8 generalised to the sliding images
// of eqs. 5.10-5.17). With `adjust_velocity` an atom moved by the image shift S gets
// v -= G S, the velocity of its image under the box's velocity gradient.
// Returns how many atoms moved.
int wrap(Atoms& atoms, const Box& box, const Mat3& g, bool adjust_velocity, int threads = 1);

}  // namespace mpmx::md
