#pragma once
// What the tiled EAM kernels share (Neighbors::tiles): each tile sums its pairs into
// arrays of its own entries; then every atom adds its shares from all tiles in tile order,
// and the energy and virial are the atoms' embedding energies, then the tiles' pair sums,
// in order. Which thread took which tile changes no number: any count gives the same bits.
#include <cstddef>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// Atom j's force from the tiles' per-entry forces `f` (4 doubles an entry: x, y, z, pad);
// with per-atom tallies, its energy (its embedding energy `embed_j` plus its entries' `e`)
// and its virial (`w6`, 6 doubles an entry).
inline void gather_shares(const Neighbors& nb, int j, const double* f, bool per_atom, double embed_j, const double* e,
                          const double* w6, ForceWork& w) {
  const int* share = nb.share.data();
  const int lo = nb.share_first[j], hi = nb.share_first[j + 1];
  double sx = 0, sy = 0, sz = 0;
  for (int v = lo; v < hi; ++v) {
    const double* fv = f + 4 * static_cast<std::size_t>(share[v]);
    sx += fv[0], sy += fv[1], sz += fv[2];
  }
  w.fx[j] = sx, w.fy[j] = sy, w.fz[j] = sz;
  if (!per_atom) return;
  double en = embed_j, v6[6] = {};
  for (int v = lo; v < hi; ++v) {
    en += e[share[v]];
    for (int c = 0; c < 6; ++c) v6[c] += w6[6 * static_cast<std::size_t>(share[v]) + c];
  }
  w.energy_atom[j] = en;
  for (int c = 0; c < 6; ++c) w.virial_atom[6 * static_cast<std::size_t>(j) + c] = v6[c];
}

// The energy and virial: every atom's embedding energy in order, then every tile's sums
// (7 doubles a tile: pair energy, then the virial's six) in order.
inline ForceSums sum_tiles(const double* embed, int nlocal, const double* tile_sums, int ntile) {
  double e = 0, v[6] = {};
  for (int j = 0; j < nlocal; ++j) e += embed[j];
  for (int p = 0; p < ntile; ++p) {
    e += tile_sums[7 * p];
    for (int c = 0; c < 6; ++c) v[c] += tile_sums[7 * p + 1 + c];
  }
  ForceSums sums;
  sums.energy = e;
  sums.virial = {v[0], v[1], v[2], v[3], v[4], v[5]};
  return sums;
}

}  // namespace mpmx::md
