#pragma once
// Initial DPD configurations: fcc blocks of mesoparticles (the seed's coarse lattice of
// constant 2a, sec. 2.2), random fills for DPD fluids, and Maxwell velocities.
#include <array>
#include <cstdint>

#include "mpmx/dpd/particles.hpp"
#include "mpmx/particles/box.hpp"

namespace mpmx::dpd {

// nx x ny x nz cubic fcc cells of lattice constant a with the lower corner at `origin`;
// ids first_id, first_id + 1, ...
Particles fcc_block(const std::array<int, 3>& cells, double a, const particles::Vec3& origin, double mass, int type,
                    std::int64_t first_id);

// `count` particles uniformly in [origin, origin + size), from the stream (seed, 0).
Particles random_block(long count, const particles::Vec3& size, const particles::Vec3& origin, double mass, int type,
                       std::int64_t first_id, std::uint64_t seed);

// Appends b's particles to a.
void append(Particles& a, const Particles& b);

// Maxwell-Boltzmann velocities at temperature_K for the mobile particles, their total
// momentum removed, scaled so the kinetic temperature (3N-3) is exact. Deterministic in
// the seed and the particles' ids (not their order).
void maxwell_velocities(Particles& p, double temperature_K, std::uint64_t seed);

}  // namespace mpmx::dpd
