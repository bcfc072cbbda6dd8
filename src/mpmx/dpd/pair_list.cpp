#include "mpmx/dpd/pair_list.hpp"

#include <algorithm>

namespace mpmx::dpd {

void PairList::build(const Particles& p, const Domain& d, double cutoff, double skin, bool sweep_order,
                     int threads) {
  nb.periodic = d.periodic;
  nb.tiles = true;
  nb.build(p, d.box, cutoff, skin, threads);
  const int n = nb.nlocal;
  const int ns = slots();
  slot_i.resize(ns);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int i = 0; i < n; ++i)
    for (int s = nb.first[i]; s < nb.first[i + 1]; ++s) slot_i[s] = i;

  sweep.clear();
  slab_first.assign(1, 0);
  phase_first.assign(kPhases + 1, 0);
  if (!sweep_order) return;
  // Slabs across the longest axis (periodic: the box; open: the particles' extent).
  int axis = 0;
  double lo = 0, len = 0;
  const std::vector<double>* c[3] = {&p.x, &p.y, &p.z};
  for (int k = 0; k < 3; ++k) {
    double a = 0, b = d.length(k);
    if (!d.periodic[k] && n > 0) {
      const auto [mn, mx] = std::minmax_element(c[k]->begin(), c[k]->end());
      a = *mn, b = *mx;
    }
    if (b - a > len) axis = k, lo = a, len = b - a;
  }
  const double rs = cutoff + skin;
  int nslab = std::max(1, static_cast<int>(len / (0.5 * rs)));
  if (d.periodic[axis]) nslab = nslab >= kPhases ? nslab - nslab % kPhases : 1;
  nslab = std::min(nslab, kPhases * 4096);
  const double inv = nslab / std::max(len, 1e-300);
  std::vector<int> slab_of(n);
  for (int i = 0; i < n; ++i) slab_of[i] = std::clamp(static_cast<int>(((*c[axis])[i] - lo) * inv), 0, nslab - 1);
  // Slabs in phase order: 0, 5, 10, ..., then 1, 6, ..., and so on.
  std::vector<int> rank(nslab);
  int r = 0;
  for (int f = 0; f < kPhases; ++f) {
    phase_first[f] = r;
    for (int b = f; b < nslab; b += kPhases) rank[b] = r++;
  }
  phase_first[kPhases] = r;
  slab_first.assign(nslab + 1, 0);
  for (int s = 0; s < ns; ++s)
    if (slot_i[s] != nb.owner[nb.list[s]]) ++slab_first[rank[slab_of[slot_i[s]]] + 1];
  for (int b = 0; b < nslab; ++b) slab_first[b + 1] += slab_first[b];
  sweep.resize(slab_first[nslab]);
  std::vector<int> fill(slab_first.begin(), slab_first.end() - 1);
  for (int s = 0; s < ns; ++s)
    if (slot_i[s] != nb.owner[nb.list[s]]) sweep[fill[rank[slab_of[slot_i[s]]]]++] = s;
}

}  // namespace mpmx::dpd
