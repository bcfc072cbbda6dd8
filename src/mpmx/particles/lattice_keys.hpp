#pragma once
// The crystal keys that md decks' [lattice] and md_closure's [material.md] share: the
// style (fcc, bcc, hcp, b2; under the key the table names it by), `orient` (three integer
// directions for x, y, z, LAMMPS's `orient`) and hcp's `c_over_a`. Problems are recorded
// against the table's keys.
#include <string_view>

#include "mpmx/core/table.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::particles {

// Reads into `spec` (its constant untouched); fcc along the cube axes when all are absent.
void read_crystal_keys(Table& t, std::string_view style_key, LatticeSpec& spec);

}  // namespace mpmx::particles
