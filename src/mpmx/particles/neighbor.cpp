#include "mpmx/particles/neighbor.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/particles/neighbor_all_pairs.hpp"
#include "mpmx/particles/neighbor_search.hpp"

namespace mpmx::particles {

namespace {
// Sorts a[0..n), values in [0, 2^bits), by least-significant-digit radix passes of at
// most 8 bits (tmp holds n): an atom's few dozen entries without the mispredicted
// comparisons of a comparison sort.
void radix_sort(int* a, int n, int* tmp, int bits) {
  const int passes = std::max(1, (bits + 7) / 8);
  const int digit = (bits + passes - 1) / passes;
  const int buckets = 1 << digit;
  int count[256];
  int* from = a;
  int* to = tmp;
  for (int p = 0, shift = 0; p < passes; ++p, shift += digit) {
    std::fill_n(count, buckets, 0);
    for (int k = 0; k < n; ++k) ++count[(from[k] >> shift) & (buckets - 1)];
    for (int b = 0, sum = 0; b < buckets; ++b) {
      const int c = count[b];
      count[b] = sum;
      sum += c;
    }
    for (int k = 0; k < n; ++k) to[count[(from[k] >> shift) & (buckets - 1)]++] = from[k];
    std::swap(from, to);
  }
  if (from != a) std::copy_n(from, n, a);
}
}  // namespace

void Neighbors::build(const Atoms& atoms, const Box& box, double rc, double sk, int threads) {
  cutoff = rc;
  skin = sk;
  const double rs = rc + sk;
  if (atoms.size() >= (1u << 30))  // the search's keys are 2 x an atom's index, in an int
    throw RunError(fmt::format("{} atoms in one system: at most 2^30 - 1", atoms.size()));
  copy_locals(atoms);
  add_ghosts(atoms, box, rs);
  const int nt = std::max(1, threads);
  all_pairs_used_ = takes_all_pairs(atoms, box, rs);
  if (all_pairs_used_) {
    all_pairs_.prepare(x.data(), y.data(), z.data(), nlocal, nall, owner.data(), n1.data(), n2.data(), n3.data(), box,
                       rs);
    list_chunks(
        [&](int i, std::vector<int>& scratch, std::vector<int>& out) { return all_pairs_.list_of(i, scratch, out); },
        nt);
  } else {
    list_pairs(bin_entries(box, rs), rs, nt);
  }
  if (tiles) build_tiles(nt);
  pack();
  remember(atoms, box);
}

void Neighbors::copy_locals(const Atoms& atoms) {
  nlocal = static_cast<int>(atoms.size());
  x.assign(atoms.x.begin(), atoms.x.end());
  y.assign(atoms.y.begin(), atoms.y.end());
  z.assign(atoms.z.begin(), atoms.z.end());
  type.assign(atoms.type.begin(), atoms.type.end());
  owner.resize(nlocal);
  for (int i = 0; i < nlocal; ++i) owner[i] = i;
  n1.assign(nlocal, 0);
  n2.assign(nlocal, 0);
  n3.assign(nlocal, 0);
}

void Neighbors::add_ghosts(const Atoms& atoms, const Box& box, double rs) {
  // Ghosts: every image within rs of the fundamental box (eqs. 5.10-5.17 with the
  // sliding offsets of the upper-triangular box).
  const bool px = periodic[0], py = periodic[1], pz = periodic[2];
  for (int i = 0; i < nlocal; ++i) {
    const double xi = atoms.x[i], yi = atoms.y[i], zi = atoms.z[i];
    const int c0 = pz ? image_index(std::ceil((-rs - zi) / box.lz)) : 0;
    const int c1 = pz ? image_index(std::floor((box.lz + rs - zi) / box.lz)) : 0;
    for (int c = c0; c <= c1; ++c) {
      const double zc = zi + c * box.lz;
      if (pz && (zc < -rs || zc >= box.lz + rs)) continue;
      const double yc0 = yi + c * box.yz;
      const int b0 = py ? image_index(std::ceil((-rs - yc0) / box.ly)) : 0;
      const int b1 = py ? image_index(std::floor((box.ly + rs - yc0) / box.ly)) : 0;
      for (int b = b0; b <= b1; ++b) {
        const double yc = yc0 + b * box.ly;
        if (py && (yc < -rs || yc >= box.ly + rs)) continue;
        const double xc0 = xi + c * box.xz + b * box.xy;
        const int a0 = px ? image_index(std::ceil((-rs - xc0) / box.lx)) : 0;
        const int a1 = px ? image_index(std::floor((box.lx + rs - xc0) / box.lx)) : 0;
        for (int a = a0; a <= a1; ++a) {
          if (a == 0 && b == 0 && c == 0) continue;
          const double xc = xc0 + a * box.lx;
          if (px && (xc < -rs || xc >= box.lx + rs)) continue;
          if (std::abs(a) > 127 || std::abs(b) > 127 || std::abs(c) > 127)
            throw RunError(fmt::format("box {} x {} x {} is too small for cutoff+skin {}", box.lx,
                                       box.ly, box.lz, rs));
          x.push_back(xc);
          y.push_back(yc);
          z.push_back(zc);
          type.push_back(atoms.type[i]);
          owner.push_back(i);
          n1.push_back(static_cast<std::int8_t>(a));
          n2.push_back(static_cast<std::int8_t>(b));
          n3.push_back(static_cast<std::int8_t>(c));
        }
      }
    }
  }
  nall = static_cast<int>(x.size());
}

bool Neighbors::takes_all_pairs(const Atoms& atoms, const Box& box, double rs) const {
  // All pairs costs per atom about its atoms times shifts per pair, the bins a constant.
  // Measured (bench/md_force_bench, BM_NeighborBuild*, one invocation): all pairs is 2.4-2.6x
  // cheaper at 500 atoms and one shift, 1.9x at 500 compressed to two shifts along z, and
  // 1.1x at 2,916 atoms and one shift; the bound leaves a margin.
  constexpr long long kAllPairsWork = 2048;
  if (search == Search::binned || tiles || !periodic[0] || !periodic[1] || !periodic[2]) return false;
  const int shifts = AllPairsSearch::shifts_per_pair(box, rs);
  if (shifts == 0) return false;
  if (search == Search::by_size && static_cast<long long>(nlocal) * shifts > kAllPairsWork) return false;
  // The filter's margin holds for atoms in the fundamental domain (build()'s contract).
  for (int i = 0; i < nlocal; ++i)
    if (!(atoms.x[i] >= 0 && atoms.x[i] < box.lx && atoms.y[i] >= 0 && atoms.y[i] < box.ly && atoms.z[i] >= 0 &&
          atoms.z[i] < box.lz))
      return false;
  return true;
}

Neighbors::Bins Neighbors::bin_entries(const Box& box, double rs) {
  // Bins over [-rs, L+rs) (no periodic wrap: ghosts are explicit); along an open axis
  // over the atoms' extent.
  Bins bins{};
  double* const lo = bins.lo;
  int* const nb = bins.n;
  double* const inv = bins.inv;
  for (int d = 0; d < 3; ++d) lo[d] = -rs;
  double ext[3] = {box.lx + 2 * rs, box.ly + 2 * rs, box.lz + 2 * rs};
  for (int d = 0; d < 3; ++d) {
    if (periodic[d] || nlocal == 0) continue;
    const std::vector<double>& c = d == 0 ? x : d == 1 ? y : z;
    const auto [mn, mx] = std::minmax_element(c.begin(), c.end());
    lo[d] = *mn;
    ext[d] = std::max(*mx - *mn, rs);
  }
  // Bins of edge >= rs/2, searched two deep: the 5^3 bins around an atom's hold about
  // 58% of the candidates that 3^3 bins of edge rs would.
  for (int d = 0; d < 3; ++d) {
    // Bounded before the cast: a box that flew apart (or went non-finite) asks for more
    // bins than an int holds.
    const double want = 2.0 * ext[d] / rs;
    nb[d] = want >= 2048.0 ? 2048 : want >= 1.0 ? static_cast<int>(want) : 1;
  }
  // Never many more bins than entries, however large and empty the box (a system that
  // flew apart, a box read from a checkpoint): fewer, larger bins hold the same pairs.
  // A bin of edge rs/2 in a solid holds a few atoms, so this never binds there.
  const long long max_bins = 8LL * nall + 4096;
  while (static_cast<long long>(nb[0]) * nb[1] * nb[2] > max_bins) {
    int& widest = *std::max_element(nb, nb + 3);
    widest = std::max(1, widest / 2);
  }
  for (int d = 0; d < 3; ++d) inv[d] = nb[d] / ext[d];
  auto bin_of = [&](int k, int d) { return bins.of(d == 0 ? x[k] : d == 1 ? y[k] : z[k], d); };
  const int nbins = nb[0] * nb[1] * nb[2];
  bin_start_.assign(nbins + 1, 0);
  std::vector<int> bin(nall);
  for (int k = 0; k < nall; ++k) {
    bin[k] = (bin_of(k, 2) * nb[1] + bin_of(k, 1)) * nb[0] + bin_of(k, 0);
    ++bin_start_[bin[k] + 1];
  }
  for (int b = 0; b < nbins; ++b) bin_start_[b + 1] += bin_start_[b];
  // The entries in bin order, their positions and keys beside them (the search reads
  // each row of bins as one run). An entry's key is 2 owner + (1 if its image shift is
  // positive): the half list keeps (i, k) iff owner(k) > i, or owner(k) == i and k's
  // shift is positive, that is iff key(k) > 2 i (one comparison, no branch).
  const std::size_t padded = static_cast<std::size_t>(nall) + kSearchPad;  // the search reads past a run
  bin_atoms_.assign(padded, 0);
  bin_key_.assign(padded, 0);
  bin_x_.assign(padded, 0.0);
  bin_y_.assign(padded, 0.0);
  bin_z_.assign(padded, 0.0);
  {
    std::vector<int> fill(bin_start_.begin(), bin_start_.end() - 1);
    for (int k = 0; k < nall; ++k) {
      const int s = fill[bin[k]]++;
      bin_atoms_[s] = k;
      bin_key_[s] = 2 * owner[k] + positive_shift(n1[k], n2[k], n3[k]);  // a local's shift is zero
      bin_x_[s] = x[k], bin_y_[s] = y[k], bin_z_[s] = z[k];
    }
  }
  return bins;
}

void Neighbors::list_pairs(const Bins bins, double rs, int nt) {
  // Half list: each physical pair exactly once (the keys above). Each atom's entries
  // ascending (locals first, then ghosts): deterministic, whoever builds it. The search
  // (neighbor_search.hpp) tests the rows of bins around the atom without a branch on the
  // unpredictable in/out decisions.
  const double rs2 = rs * rs;
  const int entry_bits = std::bit_width(static_cast<unsigned>(std::max(1, nall - 1)));
  const BinnedEntries binned{bin_x_.data(), bin_y_.data(), bin_z_.data(), bin_key_.data(), bin_atoms_.data()};
  const int* const nb = bins.n;
  auto list_of = [&](int i, std::vector<int>& cand, std::vector<int>& out) {
    const int bx = bins.of(x[i], 0), by = bins.of(y[i], 1), bz = bins.of(z[i], 2);
    const int x0 = std::max(0, bx - 2), x1 = std::min(nb[0] - 1, bx + 2);
    // Each row of up to five bins along x is one run of entries.
    int runs[2 * 25], nrun = 0, most = kSearchPad;
    for (int cz = std::max(0, bz - 2); cz <= std::min(nb[2] - 1, bz + 2); ++cz)
      for (int cy = std::max(0, by - 2); cy <= std::min(nb[1] - 1, by + 2); ++cy) {
        const int row = (cz * nb[1] + cy) * nb[0];
        runs[2 * nrun] = bin_start_[row + x0];
        runs[2 * nrun + 1] = bin_start_[row + x1 + 1];
        most += runs[2 * nrun + 1] - runs[2 * nrun];
        ++nrun;
      }
    if (cand.size() < 2 * static_cast<std::size_t>(most)) cand.resize(2 * static_cast<std::size_t>(most));
    const int n = search_runs(binned, runs, nrun, x[i], y[i], z[i], rs2, 2 * i, cand.data());
    radix_sort(cand.data(), n, cand.data() + most, entry_bits);
    out.insert(out.end(), cand.begin(), cand.begin() + n);
    return n;
  };
  list_chunks(list_of, nt);
}

template <class ListOf>
void Neighbors::list_chunks(const ListOf& list_of, int nt) {
  // Fixed chunks of atoms, each listed into its own part by whichever thread takes it,
  // then laid end to end in chunk order.
  constexpr int kChunk = 512;
  const int nchunk = (nlocal + kChunk - 1) / kChunk;
  first.assign(nlocal + 1, 0);
  if (static_cast<int>(part_.size()) < nchunk) part_.resize(nchunk);
#pragma omp parallel for schedule(dynamic) num_threads(nt) if (nt > 1)
  for (int c = 0; c < nchunk; ++c) {
    std::vector<int>& mine = part_[c];
    std::vector<int> cand;
    mine.clear();
    for (int i = c * kChunk; i < std::min(nlocal, (c + 1) * kChunk); ++i) first[i + 1] = list_of(i, cand, mine);
  }
  for (int i = 0; i < nlocal; ++i) first[i + 1] += first[i];
  list.resize(static_cast<std::size_t>(first[nlocal]));
#pragma omp parallel for schedule(static) num_threads(nt) if (nt > 1)
  for (int c = 0; c < nchunk; ++c) std::copy(part_[c].begin(), part_[c].end(), list.begin() + first[c * kChunk]);
}

void Neighbors::remember(const Atoms& atoms, const Box& box) {
  x0_.assign(atoms.x.begin(), atoms.x.end());
  y0_.assign(atoms.y.begin(), atoms.y.end());
  z0_.assign(atoms.z.begin(), atoms.z.end());
  box0_ = box;
  built_ = true;
  ++builds;
}

void Neighbors::update_positions(const Atoms& atoms, const Box& box, int threads) {
  // Only the packed copy the kernels read; x, y, z keep the build-time positions.
  if (xyz.size() != 4 * static_cast<std::size_t>(nall)) xyz.assign(4 * static_cast<std::size_t>(nall), 0.0);
  double* __restrict q = xyz.data();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int i = 0; i < nlocal; ++i) {
    q[4 * i] = atoms.x[i];
    q[4 * i + 1] = atoms.y[i];
    q[4 * i + 2] = atoms.z[i];
  }
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int k = nlocal; k < nall; ++k) {
    const int o = owner[k];
    const int a = n1[k], b = n2[k], c = n3[k];
    q[4 * k] = atoms.x[o] + (a * box.lx + b * box.xy + c * box.xz);
    q[4 * k + 1] = atoms.y[o] + (b * box.ly + c * box.yz);
    q[4 * k + 2] = atoms.z[o] + c * box.lz;
  }
}

namespace {
template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}
template <class T>
std::size_t capacity_bytes(const std::vector<T>& v) {
  return v.capacity() * sizeof(T);
}
}  // namespace

void Neighbors::shed() {
  for (auto* v : {&x, &y, &z, &xyz, &bin_x_, &bin_y_, &bin_z_}) release(*v);
  for (auto* v : {&bin_start_, &bin_atoms_, &bin_key_}) release(*v);
  release(part_);
  release(tile_part_);
  all_pairs_.release();
  // The ghosts' arrays grew by push_back (up to twice their size): kept at their size.
  for (auto* v : {&type, &owner}) v->shrink_to_fit();
  for (auto* v : {&n1, &n2, &n3}) v->shrink_to_fit();
}

std::size_t Neighbors::bytes() const {
  std::size_t b = 0;
  for (const auto* v : {&x, &y, &z, &xyz, &bin_x_, &bin_y_, &bin_z_, &x0_, &y0_, &z0_}) b += capacity_bytes(*v);
  for (const auto* v : {&type, &owner, &first, &list, &tile_atom, &tile_first, &tile_entry, &tile_list, &share_first,
                        &share, &bin_start_, &bin_atoms_, &bin_key_})
    b += capacity_bytes(*v);
  for (const auto* v : {&n1, &n2, &n3}) b += capacity_bytes(*v);
  for (const auto& p : part_) b += capacity_bytes(p);
  for (const auto& p : tile_part_) b += capacity_bytes(p);
  return b + all_pairs_.bytes();
}

void Neighbors::pack() {
  xyz.resize(4 * static_cast<std::size_t>(nall));
  for (int k = 0; k < nall; ++k) {
    xyz[4 * k] = x[k];
    xyz[4 * k + 1] = y[k];
    xyz[4 * k + 2] = z[k];
    xyz[4 * k + 3] = 0.0;
  }
}

bool Neighbors::needs_rebuild(const Atoms& atoms, const Box& box, int threads) const {
  if (!built_ || static_cast<int>(atoms.size()) != nlocal) return true;
  // The box's change since the build as the affine map A = H H0^-1 (H's columns are the
  // edge vectors; both upper triangular), which carries every build-time image shift onto
  // the current one. With d_i = x_i - A x0_i, a pair's separation moved from A r0 by
  // d_j - d_i, so |r| >= (1 - |A - I|) |r0| - 2 max|d|: no pair beyond cutoff + skin at
  // the build is within the cutoff while 2 max|d| + |A - I| (cutoff + skin) <= skin.
  // Measured from A x0 rather than x0, a box deformed with its atoms (a multiscale box
  // under its point's strain rate) spends the skin on the pairs' relative motion only.
  const Box& h0 = box0_;
  const double i00 = 1.0 / h0.lx, i11 = 1.0 / h0.ly, i22 = 1.0 / h0.lz;
  const double i01 = -h0.xy * i00 * i11, i12 = -h0.yz * i11 * i22;
  const double i02 = (h0.xy * h0.yz - h0.xz * h0.ly) * i00 * i11 * i22;
  const double a00 = box.lx * i00, a01 = box.lx * i01 + box.xy * i11, a02 = box.lx * i02 + box.xy * i12 + box.xz * i22;
  const double a11 = box.ly * i11, a12 = box.ly * i12 + box.yz * i22, a22 = box.lz * i22;
  const double strain = std::sqrt((a00 - 1) * (a00 - 1) + a01 * a01 + a02 * a02 + (a11 - 1) * (a11 - 1) +
                                  a12 * a12 + (a22 - 1) * (a22 - 1));  // Frobenius, >= the 2-norm
  const double slack = skin - strain * (cutoff + skin);
  if (slack <= 0) return true;  // a non-finite box falls through: the run's finiteness check names it
  double d2max = 0;  // a maximum: the same for any thread count
#pragma omp parallel for schedule(static) reduction(max : d2max) num_threads(threads) if (threads > 1)
  for (int i = 0; i < nlocal; ++i) {
    const double x0 = x0_[i], y0 = y0_[i], z0 = z0_[i];
    const double dx = atoms.x[i] - (a00 * x0 + a01 * y0 + a02 * z0);
    const double dy = atoms.y[i] - (a11 * y0 + a12 * z0);
    const double dz = atoms.z[i] - a22 * z0;
    d2max = std::max(d2max, dx * dx + dy * dy + dz * dz);
  }
  return 2.0 * std::sqrt(d2max) > slack;
}

void Neighbors::build_tiles(int threads) {
  // About 32 tiles, at least 2048 atoms each (unless `tile_atoms` says): enough tiles to
  // spread, few enough that the entries a tile reaches beyond its own atoms stay a small
  // multiple of them, and each tile's arrays fit a core's cache.
  const int size = tile_atoms > 0 ? tile_atoms : std::max(2048, (nlocal + 31) / 32);
  const int ntile = std::max(1, (nlocal + size - 1) / size);
  tile_atom.resize(ntile + 1);
  for (int p = 0; p <= ntile; ++p) tile_atom[p] = std::min(nlocal, p * size);
  tile_list.resize(list.size());
  if (static_cast<int>(tile_part_.size()) < ntile) tile_part_.resize(ntile);
  const int nt = std::max(1, threads);
#pragma omp parallel num_threads(nt) if (nt > 1)
  {
    std::vector<int> place(static_cast<std::size_t>(nall), -1);  // entry -> place in the tile
#pragma omp for schedule(dynamic)
    for (int p = 0; p < ntile; ++p) {
      const int a = tile_atom[p], b = tile_atom[p + 1];
      std::vector<int>& e = tile_part_[p];
      e.clear();
      for (int i = a; i < b; ++i) e.push_back(i), place[i] = 0;
      for (int s = first[a]; s < first[b]; ++s)
        if (place[list[s]] < 0) e.push_back(list[s]), place[list[s]] = 0;  // each entry once
      std::sort(e.begin() + (b - a), e.end());
      for (int u = 0; u < static_cast<int>(e.size()); ++u) place[e[u]] = u;
      for (int s = first[a]; s < first[b]; ++s) tile_list[s] = place[list[s]];
      for (int k : e) place[k] = -1;
    }
  }
  tile_first.assign(ntile + 1, 0);
  for (int p = 0; p < ntile; ++p) tile_first[p + 1] = tile_first[p] + static_cast<int>(tile_part_[p].size());
  tile_entry.resize(tile_first[ntile]);
  for (int p = 0; p < ntile; ++p) std::copy(tile_part_[p].begin(), tile_part_[p].end(), tile_entry.begin() + tile_first[p]);
  // Counting sort of the places on their entries' owners: ascending per owner.
  const int ne = tile_first[ntile];
  share_first.assign(nlocal + 1, 0);
  for (int u = 0; u < ne; ++u) ++share_first[owner[tile_entry[u]] + 1];
  for (int j = 0; j < nlocal; ++j) share_first[j + 1] += share_first[j];
  share.resize(ne);
  std::vector<int> fill(share_first.begin(), share_first.end() - 1);
  for (int u = 0; u < ne; ++u) share[fill[owner[tile_entry[u]]]++] = u;
}

void Neighbors::fold(std::vector<double>& a, int width) const {
  const std::size_t w = static_cast<std::size_t>(width);
  for (int k = nlocal; k < nall; ++k)
    for (std::size_t c = 0; c < w; ++c) a[w * owner[k] + c] += a[w * k + c];
}

void Neighbors::forward(std::vector<double>& a) const {
  for (int k = nlocal; k < nall; ++k) a[k] = a[owner[k]];
}

}  // namespace mpmx::particles
