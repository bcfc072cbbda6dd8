#pragma once
// Neighbours: ghost images of the atoms near the faces of the fundamental box (with the
// sliding-image shifts of figs. 5.2-5.3), cell binning over the box plus ghosts, and a
// half Verlet list with a skin (each pair once, Newton's third law, eq. 5.24). Rebuilt
// when a pair may have closed by the skin (the atoms' motion measured against the box's
// own affine change, so a deforming box keeps its list longer); correct for any box whose
// edges exceed the cutoff plus skin... and smaller ones too, since an atom's own images
// are ghosts like any other. An axis may be open (`periodic[d] = false`, the DPD
// engine's free surfaces): no images along it, and the bins there span the atoms' extent.
// A small box with every axis periodic skips the bins (neighbor_all_pairs.hpp): the same
// list, entry for entry, at a fraction of the cost.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "mpmx/particles/atoms.hpp"
#include "mpmx/particles/box.hpp"
#include "mpmx/particles/neighbor_all_pairs.hpp"

namespace mpmx::particles {

class Neighbors {
 public:
  // Atoms must lie in [0, L) along periodic axes (the fundamental domain System::wrap
  // and Box::image_of use, tilted box or not); along an open axis they may lie anywhere. `threads` > 1 spreads the list
  // over atoms (each atom's list is the same for any count, so is the whole).
  void build(const Atoms& atoms, const Box& box, double cutoff, double skin, int threads = 1);
  // Positions of locals and ghosts for the current atoms and box (every step).
  // `threads` > 1 spreads the copy (one big system, as DPD's); the MD boxes of a
  // multiscale run call it from their own thread with the default.
  void update_positions(const Atoms& atoms, const Box& box, int threads = 1);
  // True if some pair may have come within the cutoff unseen.
  bool needs_rebuild(const Atoms& atoms, const Box& box, int threads = 1) const;
  bool built() const { return built_; }
  // Frees what only a build or a step uses (the entries' build-time and packed positions,
  // the bins, the builders' parts), keeping the list, the ghosts' owners and images and
  // the build's positions: all that decides the next step's pairs, so a box between
  // macro steps keeps its list at a third of the bytes (update_positions restores the
  // packed positions).
  void shed();
  // Bytes held now (the arrays' capacity).
  std::size_t bytes() const;
  // The positions and box of the last build (a checkpoint rebuilds the same list from them).
  const std::vector<double>& x_at_build() const { return x0_; }
  const std::vector<double>& y_at_build() const { return y0_; }
  const std::vector<double>& z_at_build() const { return z0_; }
  const Box& box_at_build() const { return box0_; }

  // Sums ghost entries of a per-atom array (size `width` x nall) into their owners.
  void fold(std::vector<double>& a, int width = 1) const;
  // Copies owners' values to their ghosts.
  void forward(std::vector<double>& a) const;

  int nlocal = 0, nall = 0;
  std::vector<double> x, y, z;  // locals then ghosts, at the last build
  std::vector<double> xyz;      // current positions packed 4 per entry (x, y, z, 0)
  std::vector<int> type;        // locals then ghosts
  std::vector<int> owner;       // local index of each entry
  std::vector<std::int8_t> n1, n2, n3;  // image indices of each entry (0 for locals)
  std::vector<int> first;       // nlocal+1 offsets into `list`
  std::vector<int> list;        // half list: neighbour entries of each local atom
  double cutoff = 0, skin = 0;
  std::int64_t builds = 0;
  std::array<bool, 3> periodic{true, true, true};  // set before build()

  // How build() finds the pairs (the same list either way): by the size rule, a small
  // box with every axis periodic and no tiles by all pairs (neighbor_all_pairs.hpp), any
  // other by bins; or forced (tests, benches), all pairs only where it applies.
  enum class Search { by_size, binned, all_pairs };
  Search search = Search::by_size;
  // Whether the last build took all pairs.
  bool all_pairs_built() const { return all_pairs_used_; }

  // With `tiles` set before build(), the locals cut into tiles of consecutive atoms (a
  // size from the atom count alone, never from the threads), so that each tile's pairs
  // can be summed into arrays of its own, small enough for a core's cache, and each atom
  // then adds its shares in tile order: the same bits for any thread count. Tile p owns
  // atoms [tile_atom[p], tile_atom[p+1]); its entries tile_entry[tile_first[p] ..
  // tile_first[p+1]) are those atoms, then every other entry its pairs reach, ascending;
  // tile_list is `list` with each entry replaced by its place among its tile's entries.
  // The places (in all tiles' entries, end to end) that hold atom j or an image of it:
  // share[share_first[j] .. share_first[j+1]), ascending.
  bool tiles = false;
  int tile_atoms = 0;  // atoms per tile; 0: from the atom count
  std::vector<int> tile_atom, tile_first, tile_entry, tile_list, share_first, share;

 private:
  bool built_ = false;
  std::vector<double> x0_, y0_, z0_;  // local positions at build
  Box box0_;                          // box at build
  std::vector<int> bin_start_, bin_atoms_, bin_key_;  // bin order: entry, half-list key
  std::vector<double> bin_x_, bin_y_, bin_z_;
  std::vector<std::vector<int>> part_;    // the lists of chunks of atoms (build)
  std::vector<std::vector<int>> tile_part_;  // each tile's entries (build_tiles)
  AllPairsSearch all_pairs_;
  bool all_pairs_used_ = false;

  // The bins of a build: lower corner, inverse edge and count along each axis.
  struct Bins {
    double lo[3], inv[3];
    int n[3];
    int of(double p, int d) const { return std::clamp(static_cast<int>((p - lo[d]) * inv[d]), 0, n[d] - 1); }
  };
  // The steps of build(), in order.
  void copy_locals(const Atoms& atoms);
  void add_ghosts(const Atoms& atoms, const Box& box, double rs);
  bool takes_all_pairs(const Atoms& atoms, const Box& box, double rs) const;
  Bins bin_entries(const Box& box, double rs);
  void list_pairs(Bins bins, double rs, int threads);
  template <class ListOf>
  void list_chunks(const ListOf& list_of, int threads);
  void build_tiles(int threads);
  void pack();
  void remember(const Atoms& atoms, const Box& box);
};

}  // namespace mpmx::particles
