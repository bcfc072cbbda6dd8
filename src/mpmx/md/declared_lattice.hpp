#pragma once
// The crystal a potential file says its element forms (the "Z mass a lattice" line of
// setfl, fs and funcfl files), read against what a deck builds: the default lattice of a
// law whose constants come from the potential, and the warning a user needs when the
// deck puts an element on another lattice or far from its constant (Cu's atoms on Ta's
// bcc lattice run, stressed by GPa, and nothing else would say so). The line is a
// convention, not a law: CuTa.eam.alloy names Ta fcc at 4.0448 A, where the potential's
// Ta is bcc (C11, C12, C44 = 264.4, 159.5, 80.9 GPa as LAMMPS gives; fcc is not stable).
#include <optional>
#include <string>

#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

// fcc, bcc or hcp (ideal c/a) at the file's constant, for atom type `type`; nullopt where
// the file names none of them (a Lennard-Jones or Sutton-Chen potential names none).
std::optional<particles::LatticeSpec> declared_lattice(const Potential& pot, int type = 0);

// What contradicts the file (another lattice whose 0 K energy lies above the file's
// lattice's, or a constant more than 5% from the file's for the same lattice), as one
// sentence naming the element, file and both crystals; "" when nothing does. `constant`
// 0: the deck gives none (the potential's own is used).
std::string lattice_contradiction(const Potential& pot, int type, particles::LatticeStyle style, double constant);

}  // namespace mpmx::md
