#include "mpmx/dpd/cna.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mpmx::dpd {

namespace {

// Bins of edge >= rc over the particles' extent (or the periodic length).
struct Bins {
  std::array<double, 3> lo{}, len{};
  std::array<int, 3> n{};
  std::vector<int> first, next;

  int coord(int d, double x) const {
    int c = static_cast<int>(std::floor((x - lo[d]) / len[d] * n[d]));
    return std::clamp(c, 0, n[d] - 1);
  }
};

// Bonds of the largest connected cluster among the common neighbours' bonds.
int longest_chain(const std::vector<std::array<int, 2>>& bonds) {
  const int nb = static_cast<int>(bonds.size());
  std::vector<int> cluster(nb, -1);
  int best = 0;
  for (int s = 0; s < nb; ++s) {
    if (cluster[s] >= 0) continue;
    std::vector<int> stack{s};
    cluster[s] = s;
    int size = 0;
    while (!stack.empty()) {
      const int b = stack.back();
      stack.pop_back();
      ++size;
      for (int o = 0; o < nb; ++o) {
        if (cluster[o] >= 0) continue;
        const auto& x = bonds[b];
        const auto& y = bonds[o];
        if (x[0] == y[0] || x[0] == y[1] || x[1] == y[0] || x[1] == y[1]) cluster[o] = s, stack.push_back(o);
      }
    }
    best = std::max(best, size);
  }
  return best;
}

}  // namespace

std::vector<std::uint8_t> common_neighbour_analysis(const Particles& p, const Domain& d, double a) {
  const std::size_t n = p.size();
  std::vector<std::uint8_t> code(n, kOther);
  if (n == 0 || !(a > 0)) return code;
  const double rc = 0.5 * (1.0 + 1.0 / std::sqrt(2.0)) * a, rc2 = rc * rc;
  const std::vector<double>* c[3] = {&p.x, &p.y, &p.z};
  Bins bins;
  for (int k = 0; k < 3; ++k) {
    double lo = 0, hi = d.length(k);
    if (!d.periodic[k]) {
      const auto [mn, mx] = std::minmax_element(c[k]->begin(), c[k]->end());
      lo = *mn, hi = *mx + 1e-9;
    }
    bins.lo[k] = lo, bins.len[k] = hi - lo;
    bins.n[k] = std::clamp(static_cast<int>(bins.len[k] / rc), 1, 1024);
  }
  bins.first.assign(static_cast<std::size_t>(bins.n[0]) * bins.n[1] * bins.n[2], -1);
  bins.next.assign(n, -1);
  auto flat = [&](int i, int j, int k) { return (static_cast<std::size_t>(k) * bins.n[1] + j) * bins.n[0] + i; };
  std::vector<std::array<double, 3>> pos(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) pos[i][k] = d.wrap(k, (*c[k])[i]);
    const std::size_t b = flat(bins.coord(0, pos[i][0]), bins.coord(1, pos[i][1]), bins.coord(2, pos[i][2]));
    bins.next[i] = bins.first[b];
    bins.first[b] = static_cast<int>(i);
  }
  // Neighbour lists within rc, sorted (minimum image along periodic axes).
  std::vector<std::vector<int>> nb(n);
  for (std::size_t i = 0; i < n; ++i) {
    int ci[3];
    for (int k = 0; k < 3; ++k) ci[k] = bins.coord(k, pos[i][k]);
    int span[3];
    for (int k = 0; k < 3; ++k) span[k] = std::min(1, bins.n[k] / 2);  // one bin: itself only (dupes removed below)
    for (int dz = -span[2]; dz <= span[2]; ++dz)
      for (int dy = -span[1]; dy <= span[1]; ++dy)
        for (int dx = -span[0]; dx <= span[0]; ++dx) {
          int cc[3] = {ci[0] + dx, ci[1] + dy, ci[2] + dz};
          bool skip = false;
          for (int k = 0; k < 3; ++k) {
            if (cc[k] < 0 || cc[k] >= bins.n[k]) {
              if (!d.periodic[k]) skip = true;
              else cc[k] = (cc[k] + bins.n[k]) % bins.n[k];
            }
          }
          if (skip) continue;
          for (int j = bins.first[flat(cc[0], cc[1], cc[2])]; j >= 0; j = bins.next[j]) {
            if (static_cast<std::size_t>(j) == i) continue;
            double r2 = 0;
            for (int k = 0; k < 3; ++k) {
              double dd = pos[j][k] - pos[i][k];
              if (d.periodic[k]) dd -= d.length(k) * std::round(dd / d.length(k));
              r2 += dd * dd;
            }
            if (r2 < rc2) nb[i].push_back(j);
          }
        }
    std::sort(nb[i].begin(), nb[i].end());
    nb[i].erase(std::unique(nb[i].begin(), nb[i].end()), nb[i].end());
  }
  auto bonded = [&](int u, int v) { return std::binary_search(nb[u].begin(), nb[u].end(), v); };
  for (std::size_t i = 0; i < n; ++i) {
    if (nb[i].size() != 12) continue;
    int n421 = 0, n422 = 0;
    for (int j : nb[i]) {
      std::vector<int> common;
      std::set_intersection(nb[i].begin(), nb[i].end(), nb[j].begin(), nb[j].end(), std::back_inserter(common));
      if (common.size() != 4) break;
      std::vector<std::array<int, 2>> bonds;
      for (std::size_t u = 0; u < common.size(); ++u)
        for (std::size_t v = u + 1; v < common.size(); ++v)
          if (bonded(common[u], common[v])) bonds.push_back({common[u], common[v]});
      if (bonds.size() != 2) break;
      const int chain = longest_chain(bonds);
      if (chain == 1) ++n421;
      else if (chain == 2) ++n422;
      else break;
    }
    if (n421 == 12) code[i] = kFcc;
    else if (n421 == 6 && n422 == 6) code[i] = kHcp;
  }
  return code;
}

double fcc_fraction(const std::vector<std::uint8_t>& codes, const std::vector<std::uint8_t>& mask) {
  double n = 0, f = 0;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    n += 1;
    f += codes[i] == kFcc ? 1 : 0;
  }
  return n > 0 ? f / n : 0.0;
}

double interior_fcc_fraction(const Particles& p, const Domain& d, double a) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.rigid(i)) continue;
    const double x[3] = {p.x[i], p.y[i], p.z[i]};
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], x[k]), hi[k] = std::max(hi[k], x[k]);
  }
  std::vector<std::uint8_t> interior(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x[3] = {p.x[i], p.y[i], p.z[i]};
    bool in = !p.rigid(i);
    for (int k = 0; k < 3; ++k) in = in && (d.periodic[k] || (x[k] >= lo[k] + a && x[k] <= hi[k] - a));
    interior[i] = in ? 1 : 0;
  }
  return fcc_fraction(common_neighbour_analysis(p, d, a), interior);
}

}  // namespace mpmx::dpd
