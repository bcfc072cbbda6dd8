#pragma once
// The atomic planes of a lattice's periodic tile, what a sample cut from whole tiles needs
// to place its faces between planes: fcc along the cube axes is its cubic cell (planes
// every a / 2 on each axis), any other lattice and orientation its tile of
// oriented_lattice.hpp, whose planes need not be evenly spaced (hcp across [01-10]).
#include <array>
#include <cstdint>
#include <vector>

#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::particles {

struct TilePlanes {
  std::array<double, 3> length{};   // the tile's edges (Angstrom)
  std::array<double, 3> end_gap{};  // from the tile's last plane on each axis to the next tile's first (at 0)
  std::vector<double> x_planes;     // the planes across x, fractions of length[0] in [0, 1), ascending from 0
  std::int64_t atoms = 0;
};

// Throws InputError as lattice_tile does. fcc along the axes: lengths a, gaps a / 2
// (the same doubles the sample builders always used).
TilePlanes tile_planes(const LatticeSpec& spec);

}  // namespace mpmx::particles
