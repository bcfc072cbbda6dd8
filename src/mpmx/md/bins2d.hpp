#pragma once
// Fields on a 2-D grid of bins over x-y (each bin the full z length): the stress of
// eq. 2.25, first line, per bin (per-atom virial plus the kinetic part about the bin's
// own mean velocity, over the bin volume, as slab_stress does in 1-D), the mass
// density, the temperature about the bin's mean velocity and that velocity.
// Atoms outside [x0, x0 + nx dx) are ignored; y is periodic over [0, ny dy).
#include <vector>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

struct BinGrid {
  int nx = 1, ny = 1;
  double x0 = 0, dx = 1, dy = 1, lz = 1;  // Angstrom
  double volume() const { return dx * dy * lz; }
  double x_centre(int ix) const { return x0 + (ix + 0.5) * dx; }
  double y_centre(int iy) const { return (iy + 0.5) * dy; }
};

struct BinFields {
  BinGrid grid;
  // Per bin, index ix + nx * iy.
  std::vector<int> atoms;
  std::vector<double> mass;             // amu
  std::vector<double> vx, vy, vz;       // mean velocity (Angstrom/ps), 0 in an empty bin
  std::vector<Mat3> stress;             // eV/Angstrom^3, Cauchy sign
  std::vector<double> temperature;      // K, 3 (N - 1) degrees of freedom; 0 for N < 2
  double density_g_cm3(int b) const;
};

// `atoms` with on-step velocities and positions in the fundamental box (System::snapshot);
// `virial_atom` 6 per atom (System::per_atom_virial).
BinFields bin_fields(const Atoms& atoms, const std::vector<double>& type_mass,
                     const std::vector<double>& virial_atom, const BinGrid& grid);

}  // namespace mpmx::md
