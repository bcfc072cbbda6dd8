#include "mpmx/mpm/mass_distribution.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "mpmx/mpm/active_lines.hpp"
#include "mpmx/mpm/node_runs.hpp"

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
// A source with no mass near keeps what it has (no entry). Runs of lines are built
// apart and joined in order: the map of one pass over the nodes, x fastest.
template <int Dim, class Source>
void build(const Grid<Dim>& g, const std::vector<std::ptrdiff_t>& off, Source source, bool self,
           SmallMassMap& map, std::vector<SmallMassMap>& parts, int threads) {
  build_in_runs(g.lines(), threads, parts, [&](SmallMassMap& part, std::size_t begin, std::size_t end) {
    part.clear();
    for (std::size_t l = begin; l < end; ++l) {
      const std::size_t i0 = g.index(g.line_first(l));
      for (int x = g.active_lo[l]; x <= g.active_hi[l]; ++x) {  // the rest has no mass near
        const std::size_t src = i0 + static_cast<std::size_t>(x);
        if (!source(src)) continue;
        const std::uint32_t first = static_cast<std::uint32_t>(part.node.size());
        double sum = 0.0;
        for (const std::ptrdiff_t o : off) {
          const std::size_t i = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(src) + o);
          if ((o == 0 && !self) || !(g.mass[i] > 0.0)) continue;
          part.node.push_back(static_cast<std::uint32_t>(i));
          part.weight.push_back(std::sqrt(g.mass[i]));
          sum += part.weight.back();
        }
        if (part.node.size() == first) continue;
        for (std::size_t e = first; e < part.node.size(); ++e) part.weight[e] /= sum;
        part.source.push_back(static_cast<std::uint32_t>(src));
        part.start.push_back(static_cast<std::uint32_t>(part.node.size()));
      }
    }
  });
  // Joined: each part copied to its place (the counts before it) on the threads.
  const std::size_t P = parts.size();
  std::vector<std::size_t> sources(P + 1, 0), entries(P + 1, 0);
  for (std::size_t k = 0; k < P; ++k) {
    sources[k + 1] = sources[k] + parts[k].source.size();
    entries[k + 1] = entries[k] + parts[k].node.size();
  }
  map.source.resize(sources[P]);
  map.start.resize(sources[P] + 1);
  map.start[0] = 0;
  map.node.resize(entries[P]);
  map.weight.resize(entries[P]);
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (std::size_t k = 0; k < P; ++k) {
    const SmallMassMap& part = parts[k];
    const std::uint32_t base = static_cast<std::uint32_t>(entries[k]);
    std::copy(part.source.begin(), part.source.end(), map.source.begin() + sources[k]);
    for (std::size_t s = 1; s < part.start.size(); ++s) map.start[sources[k] + s] = base + part.start[s];
    std::copy(part.node.begin(), part.node.end(), map.node.begin() + entries[k]);
    std::copy(part.weight.begin(), part.weight.end(), map.weight.begin() + entries[k]);
  }
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

// v <- A^T v for every component: each source takes the weighted mean of its neighbours
// (read before the stage). One parallel region per map, the map read once for all
// components; each component's sum in the map's order, as one component alone.
template <int Dim>
void gather(const SmallMassMap& map, std::array<std::vector<double>, Dim>& v, int threads) {
  const std::size_t n = map.source.size();
  std::vector<double> mean(n * Dim, 0.0);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
#pragma omp for schedule(static)
    for (std::size_t s = 0; s < n; ++s)
      for (std::uint32_t k = map.start[s]; k < map.start[s + 1]; ++k)
        for (int a = 0; a < Dim; ++a) mean[s * Dim + a] += map.weight[k] * v[a][map.node[k]];
#pragma omp for schedule(static)
    for (std::size_t s = 0; s < n; ++s)  // sources are distinct nodes
      for (int a = 0; a < Dim; ++a) v[a][map.source[s]] = mean[s * Dim + a];
  }
}

}  // namespace

template <int Dim>
void distribute_small_mass_forces(Grid<Dim>& g, double m_eps, SmallMassMaps& maps, int threads) {
  const auto off = neighbourhood(g);
  // C0's sources: the empty nodes next to a node with mass.
  auto empty_near_mass = [&](std::size_t l) {
    if (g.mass[l] > 0.0) return false;
    for (const std::ptrdiff_t o : off)
      if (g.mass[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(l) + o)] > 0.0) return true;
    return false;
  };
  build<Dim>(g, off, empty_near_mass, false, maps.c0, maps.parts, threads);  // eq. 7.4
  build<Dim>(g, off, [&](std::size_t l) { return g.mass[l] > 0.0 && g.mass[l] <= m_eps; }, true, maps.c1,
             maps.parts, threads);  // eq. 7.5
  // The components on the threads, each in its own array: the same sums for any count.
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (int a = 0; a < Dim; ++a) {
    scatter(maps.c0, g.force[a]);
    scatter(maps.c1, g.force[a]);
  }
}

template <int Dim>
void gradient_velocities(Grid<Dim>& g, const SmallMassMaps& maps, VelocityWeights w, int threads) {
  for (auto& c : g.gradient_velocity) c.resize(g.storage);
  // On the active nodes (active_lines.hpp): the gradients read no other.
  for_each_range(g, g.active_lo, g.active_hi, threads, [&](std::size_t, std::size_t i0, int lo, int hi) {
    for (std::size_t i = i0 + static_cast<std::size_t>(lo); i <= i0 + static_cast<std::size_t>(hi); ++i)
      for (int a = 0; a < Dim; ++a) g.gradient_velocity[a][i] = w.L * g.velocity_L[a][i] + w.n * g.velocity[a][i];
  });
  adjoint_velocity<Dim>(maps, g.gradient_velocity, threads);
}

template <int Dim>
void adjoint_velocity(const SmallMassMaps& maps, std::array<std::vector<double>, Dim>& v, int threads) {
  gather<Dim>(maps.c1, v, threads);  // A1^T
  gather<Dim>(maps.c0, v, threads);  // A0^T
}

template void distribute_small_mass_forces<1>(Grid<1>&, double, SmallMassMaps&, int);
template void distribute_small_mass_forces<2>(Grid<2>&, double, SmallMassMaps&, int);
template void distribute_small_mass_forces<3>(Grid<3>&, double, SmallMassMaps&, int);
template void gradient_velocities<1>(Grid<1>&, const SmallMassMaps&, VelocityWeights, int);
template void gradient_velocities<2>(Grid<2>&, const SmallMassMaps&, VelocityWeights, int);
template void gradient_velocities<3>(Grid<3>&, const SmallMassMaps&, VelocityWeights, int);
template void adjoint_velocity<1>(const SmallMassMaps&, std::array<std::vector<double>, 1>&, int);
template void adjoint_velocity<2>(const SmallMassMaps&, std::array<std::vector<double>, 2>&, int);
template void adjoint_velocity<3>(const SmallMassMaps&, std::array<std::vector<double>, 3>&, int);

}  // namespace mpmx::mpm
