#pragma once
// The DPD pair list: the particle layer's cell-binned half Verlet list with a skin
// (particles::Neighbors: each physical pair once, ghosts for periodic images, open axes
// allowed) with its tiles (the pair forces' fixed order for any thread count,
// forces.hpp), the particle i of each slot, and optionally the order of the Shardlow
// sweep: slabs of thickness >= (cutoff + skin)/2 across the longest axis (by the
// particles' positions at the build), their number a multiple of 5 along a periodic
// axis; phase f holds the slabs k with k mod 5 = f. A pair lies within two slabs of its
// particle i's, so the pairs of two slabs of one phase share no particle: phases run in
// order, the slabs of a phase may run on different threads, each slab's pairs in slot
// order, without changing a single number. A particle's pairs with its own images are
// left out (their relative velocity is zero). The decomposition depends on the geometry
// only, never on the thread count.
#include <vector>

#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/particles.hpp"
#include "mpmx/particles/neighbor.hpp"

namespace mpmx::dpd {

class PairList {
 public:
  void build(const Particles& p, const Domain& d, double cutoff, double skin, bool sweep_order, int threads = 1);
  bool needs_rebuild(const Particles& p, const Domain& d, int threads = 1) const {
    return nb.needs_rebuild(p, d.box, threads);
  }
  void update_positions(const Particles& p, const Domain& d, int threads = 1) {
    nb.update_positions(p, d.box, threads);
  }
  int slots() const { return static_cast<int>(nb.list.size()); }
  int slabs() const { return static_cast<int>(slab_first.size()) - 1; }

  particles::Neighbors nb;               // with its tiles
  std::vector<int> slot_i;        // particle i of each slot
  std::vector<int> sweep;         // Shardlow order: slots grouped by slab, slabs by phase
  std::vector<int> slab_first;    // slab b owns sweep[slab_first[b] .. slab_first[b+1])
  std::vector<int> phase_first;   // phase f owns slabs phase_first[f] .. phase_first[f+1]-1
  static constexpr int kPhases = 5;  // slabs of half the interaction range: 2 x 2 + 1 phases
};

}  // namespace mpmx::dpd
