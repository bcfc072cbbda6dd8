#pragma once
// LAMMPS text dump of one DPD frame (OVITO reads it): id type mass x y z vx vy vz u
// [structure], u the internal energy (eV), structure the CNA code (cna.hpp) when given. md/lammps_dump.hpp writes MD frames of fully periodic boxes with
// type masses; a DPD frame also has open axes (bounds "ss", spanning the particles
// and the box) and per-particle mass and internal energy, hence this writer.
#include <cstdint>
#include <ostream>
#include <vector>

#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/particles.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

void write_lammps_dump(std::ostream& out, std::int64_t step, const Particles& p, const Domain& d,
                       const std::vector<std::uint8_t>* structure = nullptr);

}  // namespace mpmx::app::dpd
