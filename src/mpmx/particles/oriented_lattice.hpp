#pragma once
// fcc, bcc and hcp crystals in any orientation, as LAMMPS's `lattice STYLE a orient x ...
// orient y ... orient z ...` builds them, so that a box is the same input to both codes.
//
// The crystal's conventional cell is orthogonal, lengths A x B x C: a x a x a for fcc and
// bcc, a x sqrt(3) a x c for hcp (LAMMPS's four-atom hcp cell, a1 = [2-1-10], a2 = [01-10],
// a3 = [0001]). `orient` holds three integer vectors, Cartesian directions in that cell's
// frame (Miller directions [uvw] for the cubic lattices; for hcp, LAMMPS's convention: the
// same Cartesian frame, so only the cell's own axes tile a periodic box); row d becomes the
// box's axis d. The tile is the smallest orthogonal box with edges along the three that
// the crystal fills periodically: each edge the shortest lattice translation along it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/particles/lattice.hpp"

namespace mpmx::particles {

// b2 (CsCl, e.g. NiAl): bcc's sites, the corners of atom type t and the body centres of
// type t + 1 (LAMMPS: `lattice bcc` with `create_atoms 1 box basis 2 2`); a simple cubic
// lattice, so its tiles are those of sc ([111]: sqrt(3) a, not bcc's half).
enum class LatticeStyle { fcc, bcc, hcp, b2 };

using Orient = std::array<std::array<int, 3>, 3>;
inline constexpr Orient kCubeAxes = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

struct LatticeSpec {
  LatticeStyle style = LatticeStyle::fcc;
  double constant = 0;               // a, Angstrom
  double c_over_a = 1.632993161855452;  // hcp only: ideal sqrt(8/3)
  Orient orient = kCubeAxes;
  // fcc along the cube axes: the builder is particles::fcc, bit-for-bit as it always was.
  bool plain_fcc() const { return style == LatticeStyle::fcc && orient == kCubeAxes; }
};

LatticeStyle lattice_style(const std::string& name);  // "fcc", "bcc", "hcp", "b2"
const char* lattice_name(LatticeStyle s);

// The most atoms a periodic tile may hold. Large Miller indices make huge tiles ([1,1,1000]
// with its partners holds about 1e9 atoms): a tile past a material point's largest box
// is no orientation anyone means, and building it would take the machine's memory.
inline constexpr std::int64_t kMaxTileAtoms = 1'000'000;

// "" when the orientation tiles a periodic box; else why not (a zero vector, vectors not
// orthogonal, a left-handed set, an hcp direction off the cell's axes, a tile of more than
// kMaxTileAtoms atoms), naming the vectors.
std::string orient_problem(const LatticeSpec& spec);

// The atoms of the orientation's periodic tile, from its edges alone (nothing is built):
// the tile's volume over the volume per atom. The orientation must be orthogonal and
// nonzero (orient_problem's first checks); the count does not depend on the constant.
double lattice_tile_atoms(const LatticeSpec& spec);

// The smallest periodic box of the oriented crystal: edge lengths (Angstrom) and atoms.
struct LatticeTile {
  std::array<double, 3> length{};
  std::int64_t atoms = 0;
  // The atoms' fractional coordinates in the tile, each in [0, 1), ordered z, y, x, and
  // the type offset of each (b2's body centres 1, every other site 0).
  std::vector<std::array<double, 3>> sites;
  std::vector<int> kinds;
};

// Throws InputError when orient_problem is not "" (a tile past kMaxTileAtoms among its
// reasons: refused before anything is allocated) or the constant is not positive.
LatticeTile lattice_tile(const LatticeSpec& spec);

// The nearest-neighbour distance in units of a: 1/sqrt 2 (fcc), sqrt 3 / 2 (bcc), and
// for hcp min(1, sqrt(1/3 + (c/a)^2 / 4)).
double nearest_neighbour_ratio(const LatticeSpec& spec);

// tiles[d] tiles along axis d, atoms numbered from 1 in tile order, of type `type` plus
// their site's kind; the strain scales x
// and L_x by 1 + strain_x (section 6.2). fcc along the axes is particles::fcc itself.
Crystal oriented_crystal(const LatticeSpec& spec, const std::array<int, 3>& tiles, double strain_x = 0.0,
                         int type = 0);

}  // namespace mpmx::particles
