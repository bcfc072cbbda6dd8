#pragma once
// Initial DPD configurations: fcc blocks of mesoparticles (the seed's coarse lattice of
// constant 2a, sec. 2.2), random fills for DPD fluids, and Maxwell velocities.
#include <array>
#include <cstdint>

#include "mpmx/dpd/particles.hpp"
#include "mpmx/particles/box.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/rng.hpp"

namespace mpmx::dpd {

// The positions fcc_block and random_block give, in their order, without building the
// particles: site(x, y, z) for each (a deck's regions are checked against them).
template <class Site>
void fcc_sites(const std::array<int, 3>& cells, double a, const particles::Vec3& origin, Site&& site) {
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
        for (const auto& b : particles::kFccBasis)
          site(origin[0] + (i + b[0]) * a, origin[1] + (j + b[1]) * a, origin[2] + (k + b[2]) * a);
}
template <class Site>
void random_sites(long count, const particles::Vec3& size, const particles::Vec3& origin, std::uint64_t seed,
                  Site&& site) {
  particles::RngStream rng(seed, 0);
  for (long i = 0; i < count; ++i) {
    const double x = origin[0] + size[0] * rng.uniform();
    const double y = origin[1] + size[1] * rng.uniform();
    const double z = origin[2] + size[2] * rng.uniform();
    site(x, y, z);
  }
}

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
