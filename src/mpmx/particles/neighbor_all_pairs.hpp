#pragma once
// The half list of a small, fully periodic box without bins (Neighbors::build): each atom
// i against every later atom j, at each image of j that may lie within cutoff + skin. In
// a box of a few hundred atoms that is fewer candidates an atom (half the atoms) than the
// binned search tests (the entries of 5^3 bins, ghosts included, half of them kept by key),
// with no bins and no sort; in a large box far more (the size rule,
// Neighbors::takes_all_pairs). Two stages: a vector filter in single precision
// (a path per instruction set, as the binned search's) keeps each image of a j that may
// be near, with a margin that covers its rounding; then each is tested exactly as the
// binned search tests its ghost entry (the same bits: the image placed as add_ghosts
// places it, the same r^2), and mapped to its entry through a table. The entries come out
// ascending with no sort: the list is the binned search's, entry for entry.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpmx/particles/box.hpp"

namespace mpmx::particles {

// Lexicographic sign of an image shift (n1, n2, n3): of (i, image n of j) and (j, image -n
// of i) the half list keeps the one of positive shift when i == j.
inline bool positive_shift(int a, int b, int c) { return a > 0 || (a == 0 && (b > 0 || (b == 0 && c > 0))); }

// What the filter needs of the box: the image shifts to try per axis along each j (from
// the lowest one the window allows, `count` of them), as Neighbors' images go: z first,
// then y given z's shift, then x given both.
struct ImageWindow {
  float lx, ly, lz, xy, xz, yz;
  float inv[3];    // 1 / lx, 1 / ly, 1 / lz
  float lower[3];  // (radius / l + slack) per axis: the lowest shift is ceil(r / l - lower)
  float rs2;       // the filter's radius squared (cutoff + skin and its margin)
  int count[3];    // shifts to try along x, y, z
  float span[3];   // the entry table's shifts per axis: -span .. span
};

// The places the filter reads and writes past the atoms it holds (padding, masked off).
constexpr int kAllPairsPad = 16;
// More shifts per pair than this (a box much thinner than the radius): the bins instead.
constexpr int kAllPairsMostShifts = 64;

// Writes to `out`, ascending, every j in (i, n) some tried image of which may lie within
// the list radius of atom i (the window's radius), once per such image, and to `shift`
// that image's place in the entry table's row (an atom's images in the order of their
// places). Where one shift per axis is tried, a shift beyond the table's span is clamped
// to it (it holds no ghost, so no pair, and the exact stage measures the image it names);
// where several are, it is left out. x, y, z hold n + kAllPairsPad values; out and shift
// hold (n - i) x shifts per pair + kAllPairsPad.
int near_later_atoms(const float* x, const float* y, const float* z, int i, int n, const ImageWindow& w, int* out,
                     int* shift);

class AllPairsSearch {
 public:
  // Image shifts to try per pair for this box and radius (the product over the axes), or
  // 0 where the search does not apply (a non-finite box or radius, or too many shifts).
  static int shifts_per_pair(const Box& box, double rs);
  // Readies the search for a build's entries: locals [0, nlocal), then ghosts ascending
  // by owner and, per owner, by image shift (n3, n2, n1), as Neighbors::add_ghosts appends
  // them. The arrays must outlive the search's use.
  void prepare(const double* x, const double* y, const double* z, int nlocal, int nall, const int* owner,
               const std::int8_t* n1, const std::int8_t* n2, const std::int8_t* n3, const Box& box, double rs);
  // Appends atom i's half-list entries, ascending (those of Neighbors' binned search);
  // returns how many. `scratch` is the caller's, reused from atom to atom.
  int list_of(int i, std::vector<int>& scratch, std::vector<int>& out) const;
  void release();
  std::size_t bytes() const;

 private:
  const double *x_ = nullptr, *y_ = nullptr, *z_ = nullptr;
  const std::int8_t *n1_ = nullptr, *n2_ = nullptr, *n3_ = nullptr;
  int nlocal_ = 0;
  double rs2_ = 0;
  ImageWindow window_{};
  std::vector<float> xf_, yf_, zf_;  // the locals in single precision, padded
  int span_[3] = {0, 0, 0};          // the table's shifts per axis: -span .. span
  int stride_ = 0;                   // the table's places per atom
  std::vector<int> entry_;           // (atom, shift) -> entry, -1 where no ghost
  std::vector<int> ghost_first_;     // an atom's ghosts: [ghost_first[j], ghost_first[j+1])
  // Per place in an atom's row, the terms add_ghosts adds to place that image: c xz,
  // b xy, a lx, c yz, b ly, c lz.
  std::vector<std::array<double, 6>> terms_;
};

}  // namespace mpmx::particles
