#include "mpmx/mpm/mass_distribution.hpp"

#include <cmath>

namespace mpmx::mpm {

namespace {

// Storage offsets of a node's 3^d neighbourhood (the ghost layer holds the ones past
// the grid, whose mass is always zero, so no bounds test is needed).
template <int Dim>
std::vector<std::ptrdiff_t> neighbourhood(const Grid<Dim>& g) {
  std::vector<std::ptrdiff_t> off;
  const int n3 = Dim == 1 ? 3 : Dim == 2 ? 9 : 27;
  for (int c = 0; c < n3; ++c) {
    std::ptrdiff_t o = 0;
    int cc = c;
    for (int d = 0; d < Dim; ++d) {
      o += static_cast<std::ptrdiff_t>(cc % 3 - 1) * g.stride[d];
      cc /= 3;
    }
    off.push_back(o);
  }
  return off;
}

// The map of one stage: every source node l (where `source(l)`) with the nodes of mass
// in its 3^d neighbourhood (itself when `self`) and weights sqrt(m_i) / sum sqrt(m_j).
// A source with no mass near keeps what it has (no entry).
template <int Dim, class Source>
void build(const Grid<Dim>& g, const std::vector<std::ptrdiff_t>& off, Source source, bool self,
           SmallMassMap& map) {
  map.clear();
  g.for_each_node([&](std::size_t l, const std::array<int, Dim>&) {
    if (!source(l)) return;
    const std::uint32_t first = static_cast<std::uint32_t>(map.node.size());
    double sum = 0.0;
    for (const std::ptrdiff_t o : off) {
      const std::size_t i = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(l) + o);
      if ((o == 0 && !self) || !(g.mass[i] > 0.0)) continue;
      map.node.push_back(static_cast<std::uint32_t>(i));
      map.weight.push_back(std::sqrt(g.mass[i]));
      sum += map.weight.back();
    }
    if (map.node.size() == first) return;
    for (std::size_t k = first; k < map.node.size(); ++k) map.weight[k] /= sum;
    map.source.push_back(static_cast<std::uint32_t>(l));
    map.start.push_back(static_cast<std::uint32_t>(map.node.size()));
  });
}

// f <- A f: each source hands its value (read before the stage) to its neighbours.
void scatter(const SmallMassMap& map, std::vector<double>& f) {
  std::vector<double> given(map.source.size());
  for (std::size_t s = 0; s < map.source.size(); ++s) {
    given[s] = f[map.source[s]];
    f[map.source[s]] = 0.0;
  }
  for (std::size_t s = 0; s < map.source.size(); ++s)
    for (std::uint32_t k = map.start[s]; k < map.start[s + 1]; ++k) f[map.node[k]] += given[s] * map.weight[k];
}

// v <- A^T v: each source takes the weighted mean of its neighbours (read before the stage).
void gather(const SmallMassMap& map, std::vector<double>& v) {
  std::vector<double> mean(map.source.size(), 0.0);
  for (std::size_t s = 0; s < map.source.size(); ++s)
    for (std::uint32_t k = map.start[s]; k < map.start[s + 1]; ++k) mean[s] += map.weight[k] * v[map.node[k]];
  for (std::size_t s = 0; s < map.source.size(); ++s) v[map.source[s]] = mean[s];
}

}  // namespace

template <int Dim>
void distribute_small_mass_forces(Grid<Dim>& g, double m_eps, SmallMassMaps& maps) {
  const auto off = neighbourhood(g);
  // C0's sources: the empty nodes next to a node with mass, marked from the latter (most
  // of a grid is empty and far from the material).
  maps.near.assign(g.storage, 0);
  g.for_each_node([&](std::size_t i, const std::array<int, Dim>&) {
    if (g.mass[i] > 0.0)
      for (const std::ptrdiff_t o : off) maps.near[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + o)] = 1;
  });
  build<Dim>(g, off, [&](std::size_t l) { return maps.near[l] && !(g.mass[l] > 0.0); }, false, maps.c0);  // eq. 7.4
  build<Dim>(g, off, [&](std::size_t l) { return g.mass[l] > 0.0 && g.mass[l] <= m_eps; }, true, maps.c1);  // eq. 7.5
  for (int a = 0; a < Dim; ++a) {
    scatter(maps.c0, g.force[a]);
    scatter(maps.c1, g.force[a]);
  }
}

template <int Dim>
void gradient_velocities(Grid<Dim>& g, const SmallMassMaps& maps) {
  g.gradient_velocity = g.velocity;
  g.gradient_velocity_L = g.velocity_L;
  for (auto* v : {&g.gradient_velocity, &g.gradient_velocity_L})
    for (int a = 0; a < Dim; ++a) adjoint_velocity(maps, (*v)[a]);
}

void adjoint_velocity(const SmallMassMaps& maps, std::vector<double>& v) {
  gather(maps.c1, v);  // A1^T
  gather(maps.c0, v);  // A0^T
}

template void distribute_small_mass_forces<1>(Grid<1>&, double, SmallMassMaps&);
template void distribute_small_mass_forces<2>(Grid<2>&, double, SmallMassMaps&);
template void distribute_small_mass_forces<3>(Grid<3>&, double, SmallMassMaps&);
template void gradient_velocities<1>(Grid<1>&, const SmallMassMaps&);
template void gradient_velocities<2>(Grid<2>&, const SmallMassMaps&);
template void gradient_velocities<3>(Grid<3>&, const SmallMassMaps&);

}  // namespace mpmx::mpm
