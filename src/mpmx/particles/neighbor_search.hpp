#pragma once
// The candidate filter of the neighbour-list build (Neighbors::build): of the entries in
// runs of bins, those within the list radius of an atom and after it in the half list's
// order. A path per instruction set (Google Highway), chosen at run time as the EAM
// kernel's (core/isa.hpp); every path writes the entries the scalar path writes.

namespace mpmx::particles {

// The entries in bin order, one array per field: position, half-list key (2 owner + 1
// for a ghost whose image shift is positive) and entry index.
struct BinnedEntries {
  const double* x;
  const double* y;
  const double* z;
  const int* key;
  const int* entry;
};

// The search reads up to this many places past a run's end (masked off), so the binned
// arrays carry that many more, and writes up to this many past the entries it keeps.
constexpr int kSearchPad = 16;

// Writes to `out`, in run order, entry[s] for every s in the runs [run[2r], run[2r+1])
// (r < nrun) with (xi - x[s])^2 + (yi - y[s])^2 + (zi - z[s])^2 < rs2 (summed in that
// order, never fused) and key[s] > twice_i; returns how many. `out` holds the runs'
// total plus kSearchPad.
int search_runs(const BinnedEntries& b, const int* run, int nrun, double xi, double yi, double zi, double rs2,
                int twice_i, int* out);

}  // namespace mpmx::particles
