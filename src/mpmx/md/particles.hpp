#pragma once
// The particle layer (particles/: atoms, periodic box, lattices, random streams,
// neighbour lists, force sums) under the MD engine's own names, so that md/ code and its
// callers say md::Box, md::Atoms, md::fcc as they always have. The only place md/ names
// particles:: types by using-declarations.
#include "mpmx/particles/atoms.hpp"
#include "mpmx/particles/box.hpp"
#include "mpmx/particles/force_sums.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/neighbor.hpp"
#include "mpmx/particles/rng.hpp"

namespace mpmx::md {

using particles::Atoms;
using particles::Box;
using particles::Crystal;
using particles::fcc;
using particles::ForceSums;
using particles::is_upper_triangular;
using particles::Mat3;
using particles::Neighbors;
using particles::RngStream;
using particles::Sym6;
using particles::upper_triangular;
using particles::Vec3;

}  // namespace mpmx::md
