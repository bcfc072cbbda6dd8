#pragma once
// The pairs a neighbour list should hold, by brute force, and those it does hold, as
// sets of (i, j, image of j relative to i) with i <= j: what the neighbour tests compare.
#include <gtest/gtest.h>

#include <array>
#include <set>
#include <tuple>

#include "mpmx/particles/neighbor.hpp"

namespace mpmx::test {

using Pair = std::tuple<int, int, int, int, int>;

inline Pair canonical(int i, int j, int a, int b, int c) {
  if (i > j || (i == j && std::make_tuple(a, b, c) < std::make_tuple(0, 0, 0))) return {j, i, -a, -b, -c};
  return {i, j, a, b, c};
}

// Every pair of atoms (any image, up to three boxes away, along the periodic axes) closer
// than r.
inline std::set<Pair> pairs_within(const particles::Atoms& at, const particles::Box& box, double r,
                                   const std::array<bool, 3>& periodic = {true, true, true}) {
  std::set<Pair> out;
  const int n = static_cast<int>(at.size());
  const int ra = periodic[0] ? 3 : 0, rb = periodic[1] ? 3 : 0, rc = periodic[2] ? 3 : 0;
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j)
      for (int a = -ra; a <= ra; ++a)
        for (int b = -rb; b <= rb; ++b)
          for (int c = -rc; c <= rc; ++c) {
            if (i == j && a == 0 && b == 0 && c == 0) continue;
            const auto s = box.shift(a, b, c);
            const double dx = at.x[j] + s[0] - at.x[i], dy = at.y[j] + s[1] - at.y[i], dz = at.z[j] + s[2] - at.z[i];
            if (dx * dx + dy * dy + dz * dz < r * r) out.insert(canonical(i, j, a, b, c));
          }
  return out;
}

// The list's pairs; a test failure where one is listed twice or an atom's entries are
// not ascending.
inline std::set<Pair> listed(const particles::Neighbors& nb) {
  std::set<Pair> out;
  for (int i = 0; i < nb.nlocal; ++i)
    for (int s = nb.first[i]; s < nb.first[i + 1]; ++s) {
      const int k = nb.list[s];
      EXPECT_TRUE(s == nb.first[i] || nb.list[s - 1] < k) << "atom " << i << ": entries not ascending";
      EXPECT_TRUE(out.insert(canonical(i, nb.owner[k], nb.n1[k], nb.n2[k], nb.n3[k])).second)
          << "atom " << i << ": a pair listed twice";
    }
  return out;
}

}  // namespace mpmx::test
