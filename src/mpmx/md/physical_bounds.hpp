#pragma once
// What an atom of metal-unit MD can physically be, for refusing inputs that cannot be
// right before anything is computed with them: a mass from below the lightest atom
// (hydrogen, 1.008 amu) to beyond the heaviest (about 300 amu), with room for a coarse
// "atom" of a few, and the shortest distance two atoms of a crystal may start at (no bond
// is shorter than about 0.74 A, H2's; metals' neighbours are 2-3 A apart).
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace mpmx::md {

inline constexpr double kMinAtomMass = 0.5;     // amu
inline constexpr double kMaxAtomMass = 1000.0;  // amu
inline constexpr double kMinBondLength = 1.0;   // Angstrom: a crystal's nearest neighbours

// "" when `mass` (amu) is an atom's, else why not (for a message after "mass = ...: ").
inline std::string atom_mass_problem(double mass) {
  if (mass >= kMinAtomMass && mass <= kMaxAtomMass) return {};
  return fmt::format("an atom's mass lies in [{}, {}] amu (metal units)", kMinAtomMass, kMaxAtomMass);
}

// "" when an fcc lattice of constant `a` (Angstrom) puts its nearest neighbours, a / sqrt 2
// apart, at least a bond apart; else why not (0.1 A put 2 million neighbours inside
// copper's cutoff, so that `check` alone took 90 s and 11.7 GB to time the box).
inline std::string fcc_constant_problem(double a) {
  const double nn = a / std::sqrt(2.0);
  if (!(a > 0) || nn >= kMinBondLength) return {};
  return fmt::format("fcc nearest neighbours would be {:.4g} A apart (constant / sqrt 2), closer than any bond "
                     "({} A): the atoms would start inside each other",
                     nn, kMinBondLength);
}

// The same for any lattice whose nearest neighbours lie `ratio` times the constant apart
// (particles::nearest_neighbour_ratio); `lattice` names it in the message.
inline std::string lattice_constant_problem(double a, double ratio, const char* lattice) {
  const double nn = a * ratio;
  if (!(a > 0) || nn >= kMinBondLength) return {};
  return fmt::format("{} nearest neighbours would be {:.4g} A apart ({:.4g} x the constant), closer than any bond "
                     "({} A): the atoms would start inside each other",
                     lattice, nn, ratio, kMinBondLength);
}

}  // namespace mpmx::md
