#pragma once
// LAMMPS text dump of one MD frame (OVITO and LAMMPS read it): id type x y z vx vy vz and
// any per-atom columns after them, one row an atom in the order of its id,
// with the box as LAMMPS writes a triclinic cell (a = (lx,0,0), b = (xy,ly,0),
// c = (xz,yz,lz)); positions are those of the rectangular fundamental box, equivalent
// modulo the image lattice.
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "mpmx/md/particles.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::md {

// A per-atom column: its name in the ITEM: ATOMS line and a value per atom (atoms' order).
struct DumpColumn {
  std::string name;
  std::vector<double> values;
};

void write_lammps_dump(std::ostream& out, std::int64_t step, const Atoms& atoms, const Box& box,
                       const std::vector<DumpColumn>& more = {});

// The per-atom fields a deck may ask of a dump (run.dump_fields), in the columns they
// write: "pe" (eV), "stress" (GPa, stress.hpp's atom_stress: sxx syy szz sxy sxz syz),
// "structure" (md/structure.hpp's a-CNA label, OVITO's numbering).
const std::vector<std::string>& dump_field_names();
// Whether a System must keep per-atom sums (SystemOptions::per_atom) for these fields.
bool dump_needs_per_atom(const std::vector<std::string>& fields);
// What is wrong with a deck's list of fields (a name not among them, one named twice), or "".
std::string dump_fields_problem(const std::vector<std::string>& fields);

// One frame of a System's current state with the named fields after the positions and
// velocities; the structure is found within the potential's cut-off. `step`: the
// TIMESTEP written (-1: the system's own step).
void write_dump_frame(std::ostream& out, const System& sys, const std::vector<std::string>& fields, int threads = 1,
                      std::int64_t step = -1);

}  // namespace mpmx::md
