#pragma once
// Grids of unequal cell sides and random points on them, for the shape tests.
#include <random>

#include "mpmx/mpm/grid.hpp"
#include "mpmx/mpm/particles.hpp"

namespace mpmx::test {

template <int Dim>
mpm::Grid<Dim> uneven_grid() {
  if constexpr (Dim == 1) return mpm::Grid<1>({-1.0}, {3.0}, {20});
  else if constexpr (Dim == 2) return mpm::Grid<2>({0.0, -0.5}, {2.0, 0.5}, {8, 5});
  else return mpm::Grid<3>({0.0, -0.5, 1.0}, {2.0, 0.5, 1.6}, {8, 5, 4});
}

// Points at random places from `margin` cells inside each end (negative: past the
// ends), domains of about a third of a cell, sheared a little; random velocities and
// stresses, volume the domain's, mass 1-2 times the volume.
template <int Dim>
mpm::Particles<Dim> random_particles(const mpm::Grid<Dim>& g, std::size_t n, unsigned seed, double margin) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  mpm::Particles<Dim> p;
  p.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    double V = 1.0;
    for (int a = 0; a < Dim; ++a) {
      p.x[a][q] = g.lower[a] + g.dx[a] * (margin + (g.cells[a] - 2.0 * margin) * u(rng));
      p.v[a][q] = u(rng) - 0.5;
      for (int b = 0; b < Dim; ++b) {
        p.length[a * Dim + b][q] = a == b ? g.dx[a] * (0.25 + 0.2 * u(rng)) : 0.05 * g.dx[a] * (u(rng) - 0.5);
        p.stress[a * Dim + b][q] = u(rng) - 0.5;
      }
      V *= p.length[a * Dim + a][q];
    }
    p.volume[q] = p.volume0[q] = V;
    p.mass[q] = V * (1.0 + u(rng));
  }
  return p;
}

}  // namespace mpmx::test
