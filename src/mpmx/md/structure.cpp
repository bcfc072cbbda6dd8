#include "mpmx/md/structure.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <numeric>

#include "mpmx/particles/neighbor.hpp"

namespace mpmx::md {

std::string_view structure_name(Structure s) {
  switch (s) {
    case Structure::fcc: return "fcc";
    case Structure::hcp: return "hcp";
    case Structure::bcc: return "bcc";
    case Structure::ico: return "ico";
    default: return "other";
  }
}

namespace {

using Vec = std::array<double, 3>;

// One neighbour's common-neighbour signature (Honeycutt-Andersen): how many of the atom's
// neighbours it shares, the bonds among those, and the bonds of the largest connected
// group of them (the "longest chain": 1 for 421, 2 for 422, 4, 5, 6 for the rings).
struct Signature {
  int common = 0, bonds = 0, chain = 0;
  bool is(int a, int b, int c) const { return common == a && bonds == b && chain == c; }
};

Signature signature(const std::array<std::uint32_t, 14>& bonded, int j) {
  Signature s;
  const std::uint32_t common = bonded[j];
  s.common = std::popcount(common);
  int twice = 0;
  for (std::uint32_t m = common; m; m &= m - 1) twice += std::popcount(bonded[std::countr_zero(m)] & common);
  s.bonds = twice / 2;
  // The groups of the common neighbours joined by bonds; each group's bonds.
  std::uint32_t left = common;
  while (left) {
    std::uint32_t group = left & (~left + 1), grown = 0;
    while (grown != group) {
      grown = group;
      for (std::uint32_t m = group; m; m &= m - 1) group |= bonded[std::countr_zero(m)] & common;
    }
    left &= ~group;
    int deg = 0;
    for (std::uint32_t m = group; m; m &= m - 1) deg += std::popcount(bonded[std::countr_zero(m)] & group);
    s.chain = std::max(s.chain, deg / 2);
  }
  return s;
}

// The bonds among the n nearest neighbours v[0..n) under the local cut-off rc.
std::array<std::uint32_t, 14> bonds_among(const Vec* v, int n, double rc) {
  std::array<std::uint32_t, 14> bonded{};
  const double rc2 = rc * rc;
  for (int j = 0; j < n; ++j)
    for (int k = j + 1; k < n; ++k) {
      const double dx = v[j][0] - v[k][0], dy = v[j][1] - v[k][1], dz = v[j][2] - v[k][2];
      if (dx * dx + dy * dy + dz * dz < rc2) bonded[j] |= 1u << k, bonded[k] |= 1u << j;
    }
  return bonded;
}

// v sorted by length, r their lengths: fcc, hcp or ico from the 12 nearest, bcc from the
// 14 nearest (the local cut-offs of a-CNA, Stukowski 2012 eqs. 4-5).
Structure classify(const Vec* v, const double* r, int n) {
  const double half_gap = (1 + std::sqrt(2.0)) / 2;  // halfway between the first two shells
  if (n >= 12) {
    const double rc = half_gap * std::accumulate(r, r + 12, 0.0) / 12;
    const auto bonded = bonds_among(v, 12, rc);
    int n421 = 0, n422 = 0, n555 = 0;
    for (int j = 0; j < 12; ++j) {
      const Signature s = signature(bonded, j);
      n421 += s.is(4, 2, 1), n422 += s.is(4, 2, 2), n555 += s.is(5, 5, 5);
    }
    if (n421 == 12) return Structure::fcc;
    if (n421 == 6 && n422 == 6) return Structure::hcp;
    if (n555 == 12) return Structure::ico;
  }
  if (n >= 14) {
    // bcc's first shell at sqrt(3)/2 a, its second at a: both scaled to the second.
    const double r8 = std::accumulate(r, r + 8, 0.0) / 8, r6 = std::accumulate(r + 8, r + 14, 0.0) / 6;
    const double rc = half_gap * (2 / std::sqrt(3.0) * r8 + r6) / 2;
    const auto bonded = bonds_among(v, 14, rc);
    int n444 = 0, n666 = 0;
    for (int j = 0; j < 14; ++j) {
      const Signature s = signature(bonded, j);
      n444 += s.is(4, 4, 4), n666 += s.is(6, 6, 6);
    }
    if (n666 == 8 && n444 == 6) return Structure::bcc;
  }
  return Structure::other;
}

}  // namespace

std::vector<Structure> adaptive_cna(const Atoms& atoms, const Box& box, double reach, int threads) {
  const int n = static_cast<int>(atoms.size());
  std::vector<Structure> out(static_cast<std::size_t>(n), Structure::other);
  if (n == 0) return out;
  particles::Neighbors nb;
  nb.build(atoms, box, reach, 0.0, threads);
  // Every atom's neighbour vectors from the half list: each pair to both of its atoms
  // (a ghost's to its owner, reversed).
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
  for (int i = 0; i < n; ++i)
    for (int s = nb.first[i]; s < nb.first[i + 1]; ++s) ++start[i + 1], ++start[nb.owner[nb.list[s]] + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<Vec> vec(static_cast<std::size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int i = 0; i < n; ++i)
    for (int s = nb.first[i]; s < nb.first[i + 1]; ++s) {
      const int k = nb.list[s];
      const Vec d{nb.x[k] - nb.x[i], nb.y[k] - nb.y[i], nb.z[k] - nb.z[i]};
      vec[fill[i]++] = d;
      vec[fill[nb.owner[k]]++] = {-d[0], -d[1], -d[2]};
    }
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    std::vector<std::pair<double, int>> by_length;
#pragma omp for schedule(static)
    for (int i = 0; i < n; ++i) {
      const int a = start[i], m = start[i + 1] - a;
      by_length.clear();
      for (int j = 0; j < m; ++j) {
        const Vec& d = vec[a + j];
        by_length.emplace_back(d[0] * d[0] + d[1] * d[1] + d[2] * d[2], j);
      }
      const int keep = std::min(m, 14);
      std::partial_sort(by_length.begin(), by_length.begin() + keep, by_length.end());
      Vec v[14];
      double r[14];
      for (int j = 0; j < keep; ++j) v[j] = vec[a + by_length[j].second], r[j] = std::sqrt(by_length[j].first);
      out[i] = classify(v, r, keep);
    }
  }
  return out;
}

}  // namespace mpmx::md
