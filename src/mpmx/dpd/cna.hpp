#pragma once
// Common neighbour analysis (Honeycutt and Andersen 1987) with a fixed cutoff from the
// lattice constant: r_c = (1 + 1/sqrt 2) a / 2, between the first (a/sqrt 2) and second
// (a) fcc shells. A particle with 12 neighbours whose 12 pair signatures (common
// neighbours, bonds among them, longest chain of bonds) are all (4, 2, 1) is fcc; six
// (4, 2, 1) and six (4, 2, 2) is hcp; anything else "other". Seed 004 fig. 4 uses it with
// the coarse lattice constant (2a for mesoparticles of 8 atoms). Codes follow OVITO's
// structure types: 0 other, 1 fcc, 2 hcp.
#include <cstdint>
#include <vector>

#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/particles.hpp"

namespace mpmx::dpd {

enum Structure : std::uint8_t { kOther = 0, kFcc = 1, kHcp = 2 };

std::vector<std::uint8_t> common_neighbour_analysis(const Particles& p, const Domain& d, double lattice_constant);

// Fraction of `codes` equal to kFcc over the particles selected by `mask` (all when empty).
double fcc_fraction(const std::vector<std::uint8_t>& codes, const std::vector<std::uint8_t>& mask = {});

// CNA's fcc fraction over the mobile particles at least one lattice constant inside their
// bounding box along every open axis (a free surface is never fcc by CNA).
double interior_fcc_fraction(const Particles& p, const Domain& d, double lattice_constant);

}  // namespace mpmx::dpd
