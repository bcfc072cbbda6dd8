#pragma once
// What a potential writes: forces on locals and ghosts (folded into the owners by the
// caller), the total energy and the pair virial (ForceSums, particles/force_sums.hpp).
#include <vector>

#include "mpmx/md/particles.hpp"

namespace mpmx::md {

struct ForceWork {
  std::vector<double> fx, fy, fz;    // size nall
  std::vector<double> rho, fp;       // EAM density and F'(rho), size nall
  bool per_atom = false;             // also fill energy_atom and virial_atom
  bool tally = true;                 // energy and virial wanted (else forces only)
  std::vector<double> energy_atom;   // size nall
  std::vector<double> virial_atom;   // 6 * nall, half of each pair to each atom
  // Set by a kernel that already summed ghost forces (and per-atom tallies) into their
  // owners (valid for locals only).
  bool folded = false;
  // Threads for a list with tiles (Neighbors::tiles): the EAM kernels (the one-element
  // tables, and the generic one of several elements and of Sutton-Chen) sum their pairs
  // tile by tile and every atom adds its tiles' shares in a fixed order, so any count
  // gives the same bits. Lennard-Jones runs on one thread.
  int threads = 1;
  // Sizes the arrays and zeroes rho (and the per-atom sums); each kernel zeroes the
  // force arrays it accumulates into (zero_forces()).
  void reset(int nall);
  void zero_forces();
};

}  // namespace mpmx::md
