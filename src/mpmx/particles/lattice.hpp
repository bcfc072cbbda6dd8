#pragma once
// Crystal builders. An fcc block of n x n x n cubic cells as in section 6.2: lattice
// constant a, and an initial engineering strain along x applied to both the atoms'
// x-coordinates and the box length (x and L_x multiplied by 1 + e0).
#include "mpmx/particles/atoms.hpp"
#include "mpmx/particles/box.hpp"

namespace mpmx::particles {

// The four sites of the cubic fcc cell, in units of the lattice constant.
inline constexpr double kFccBasis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};

struct Crystal {
  Atoms atoms;
  Box box;
};

Crystal fcc(int nx, int ny, int nz, double lattice_constant, double strain_x = 0.0,
            int type = 0);

}  // namespace mpmx::particles
