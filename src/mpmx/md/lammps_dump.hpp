#pragma once
// LAMMPS text dump of one MD frame (OVITO and LAMMPS read it): id type x y z vx vy vz,
// with the box as LAMMPS writes a triclinic cell (a = (lx,0,0), b = (xy,ly,0),
// c = (xz,yz,lz)); positions are those of the rectangular fundamental box, equivalent
// modulo the image lattice.
#include <cstdint>
#include <ostream>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

void write_lammps_dump(std::ostream& out, std::int64_t step, const Atoms& atoms, const Box& box);

}  // namespace mpmx::md
