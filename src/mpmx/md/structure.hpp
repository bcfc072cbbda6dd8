#pragma once
// Each atom's local crystal structure by adaptive common neighbour analysis (a-CNA,
// Stukowski, Modelling Simul. Mater. Sci. Eng. 20, 045021, 2012): the cut-off that
// decides which neighbours are bonded is set per atom from its own nearest distances, so
// a compressed, stretched or hot crystal is still told apart from a defect without a
// cut-off chosen by hand. The labels are OVITO's, so its colour coding applies to a dump.
#include <cstdint>
#include <string_view>
#include <vector>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

enum class Structure : std::uint8_t { other = 0, fcc = 1, hcp = 2, bcc = 3, ico = 4 };

std::string_view structure_name(Structure s);

// The label of every atom (in the atoms' order). Atoms in the fundamental box (as
// System::snapshot gives them); `reach` must hold an atom's 14 nearest neighbours in a
// bcc crystal and its 12 in fcc or hcp (a metal potential's cut-off does: 4.5-6 A
// against 2.9-3.6 A): an atom with fewer neighbours within it is `other`. The same
// labels on any thread count (each atom's is its own).
std::vector<Structure> adaptive_cna(const Atoms& atoms, const Box& box, double reach, int threads = 1);

}  // namespace mpmx::md
