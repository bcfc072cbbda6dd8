// Micro-benchmarks of the MD engine: ten leapfrog steps of fcc Cu (Cu_mishin1) at 500
// and 32,000 atoms, double and mixed precision, beside bcc Fe (Fe_mm, a = 2.8553) at 432
// and 31,250 atoms along [100] and 32,000 along [110] (M6: the new lattices at the engine's
// rate, atom_steps_per_s of each in one invocation); and one neighbour-list build of the same
// crystals (skin 1 A), whose cost against a step's is what a box that rebuilds often
// (a multiscale box under shear and shock) pays: by the size rule, and by bins and by all
// pairs side by side (also in a box compressed by 30%), where the size rule's bound comes
// from. Two floors of the half-list layout on the same list, which no EAM kernel over it
// can beat: the gather floor (each candidate's position loaded, r^2 formed and compared
// with the cut-off: once a step, as the kernel's density pass keeps the pairs it finds for
// the force pass) and the scatter floor (each pair within the cut-off adding a force to
// both atoms). A kernel's step against their sum is how near the layout's limit it runs.
// Beside them, what a cluster layout would evaluate in the same box (BM_ClusterLanes).
#include <algorithm>
#include <cmath>
#include <vector>
#include <benchmark/benchmark.h>

#include "mpmx/md/integrate.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/neighbor.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

using namespace mpmx::md;

namespace {
System make(int cells, bool mixed) {
  EamSpec spec;
  spec.file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";
  SystemOptions o;
  o.mixed_precision = mixed;
  System s(fcc(cells, cells, cells, 3.615), Potential(spec), o);
  s.thermalize(300, 1, 0);
  s.advance(20, 0.001);
  return s;
}

void BM_MdStep(benchmark::State& state) {
  System s = make(static_cast<int>(state.range(0)), state.range(1) != 0);
  for (auto _ : state) s.advance(10, 0.001);
  state.counters["atom_steps_per_s"] =
      benchmark::Counter(static_cast<double>(s.atoms().size()) * 10 * state.iterations(), benchmark::Counter::kIsRate);
}

// bcc Fe, tiles^3 periodic tiles along [100] (orient 0) or [110] (orient 1), 300 K.
System make_bcc(int tiles, int orient) {
  EamSpec spec;
  spec.file = "/usr/share/lammps/potentials/Fe_mm.eam.fs";
  spec.elements = {"Fe"};
  mpmx::particles::LatticeSpec l;
  l.style = mpmx::particles::LatticeStyle::bcc;
  l.constant = 2.8553;
  if (orient == 1) l.orient = {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};
  System s(mpmx::particles::oriented_crystal(l, {tiles, tiles, tiles}), Potential(spec), SystemOptions{});
  s.thermalize(300, 1, 0);
  s.advance(20, 0.001);
  return s;
}

void BM_MdStepBcc(benchmark::State& state) {
  System s = make_bcc(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  for (auto _ : state) s.advance(10, 0.001);
  state.counters["atom_steps_per_s"] =
      benchmark::Counter(static_cast<double>(s.atoms().size()) * 10 * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["atoms"] = static_cast<double>(s.atoms().size());
}

// One build by the size rule, or by the path the second argument forces (1: bins, 2: all
// pairs), the paths' costs side by side in one invocation.
void BM_NeighborBuild(benchmark::State& state) {
  const System s = make(static_cast<int>(state.range(0)), false);
  // The atoms in the fundamental box, as System::rebuild hands them over.
  mpmx::particles::Atoms at = s.atoms();
  mpmx::md::wrap(at, s.box(), mpmx::particles::Mat3{}, false);
  Neighbors nb;
  if (state.range(1) == 1) nb.search = Neighbors::Search::binned;
  if (state.range(1) == 2) nb.search = Neighbors::Search::all_pairs;
  for (auto _ : state) {
    nb.build(at, s.box(), s.potential().cutoff(), 1.0);
    benchmark::DoNotOptimize(nb.list.data());
  }
  state.counters["atoms_per_s"] =
      benchmark::Counter(static_cast<double>(s.atoms().size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["pairs_per_atom"] = static_cast<double>(nb.list.size()) / s.atoms().size();
  state.counters["all_pairs"] = nb.all_pairs_built();
}
// The same box as a hot point's late in a jet: compressed by 30% along z and sheared
// (xz = 0.1 lz), thinner than twice the list radius along z; by path (1: bins, 2: all pairs).
void BM_NeighborBuildCompressed(benchmark::State& state) {
  const System s = make(static_cast<int>(state.range(0)), false);
  mpmx::particles::Atoms at = s.atoms();
  mpmx::particles::Box box = s.box();
  for (std::size_t i = 0; i < at.size(); ++i) at.z[i] *= 0.7, at.x[i] += 0.1 * at.z[i];
  box.lz *= 0.7;
  box.xz = 0.1 * box.lz;
  mpmx::md::wrap(at, box, mpmx::particles::Mat3{}, false);
  Neighbors nb;
  nb.search = state.range(1) == 1 ? Neighbors::Search::binned : Neighbors::Search::all_pairs;
  for (auto _ : state) {
    nb.build(at, box, s.potential().cutoff(), 1.0);
    benchmark::DoNotOptimize(nb.list.data());
  }
  state.counters["atoms_per_s"] =
      benchmark::Counter(static_cast<double>(at.size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["pairs_per_atom"] = static_cast<double>(nb.list.size()) / at.size();
  state.counters["all_pairs"] = nb.all_pairs_built();
}
void BM_GatherFloor(benchmark::State& state) {
  const System s = make(static_cast<int>(state.range(0)), false);
  Neighbors nb;
  nb.build(s.atoms(), s.box(), s.potential().cutoff(), 1.0);
  const double cutsq = s.potential().cutoff() * s.potential().cutoff();
  const double* q = nb.xyz.data();
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < nb.nlocal; ++i)
      for (int t = nb.first[i]; t < nb.first[i + 1]; ++t) {
        const int k = nb.list[t];
        const double dx = q[4 * i] - q[4 * k], dy = q[4 * i + 1] - q[4 * k + 1], dz = q[4 * i + 2] - q[4 * k + 2];
        const double rsq = dx * dx + dy * dy + dz * dz;
        acc += rsq < cutsq ? rsq : 0.0;
      }
    benchmark::DoNotOptimize(acc);
  }
  state.counters["atom_steps_per_s"] =
      benchmark::Counter(static_cast<double>(nb.nlocal) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["candidates_per_atom"] = static_cast<double>(nb.list.size()) / nb.nlocal;
}

// The pairs within the cut-off (found once, with c = 1/r), each adding dx * c to one atom
// and taking it from the other: the force pass's scatter alone.
void BM_ScatterFloor(benchmark::State& state) {
  const System s = make(static_cast<int>(state.range(0)), false);
  Neighbors nb;
  nb.build(s.atoms(), s.box(), s.potential().cutoff(), 1.0);
  const double cutsq = s.potential().cutoff() * s.potential().cutoff();
  std::vector<int> pi, pk;
  std::vector<double> d, c;
  const double* q = nb.xyz.data();
  for (int i = 0; i < nb.nlocal; ++i)
    for (int t = nb.first[i]; t < nb.first[i + 1]; ++t) {
      const int k = nb.list[t];
      const double dx = q[4 * i] - q[4 * k], dy = q[4 * i + 1] - q[4 * k + 1], dz = q[4 * i + 2] - q[4 * k + 2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < cutsq) pi.push_back(i), pk.push_back(k), d.insert(d.end(), {dx, dy, dz}), c.push_back(1 / std::sqrt(rsq));
    }
  std::vector<double> f(3 * static_cast<std::size_t>(nb.nall), 0.0);
  for (auto _ : state) {
    for (std::size_t p = 0; p < pi.size(); ++p) {
      const double dx = d[3 * p], dy = d[3 * p + 1], dz = d[3 * p + 2];
      const double cp = c[p];
      double* fi = &f[3 * static_cast<std::size_t>(pi[p])];
      double* fk = &f[3 * static_cast<std::size_t>(pk[p])];
      fi[0] += dx * cp, fi[1] += dy * cp, fi[2] += dz * cp;
      fk[0] -= dx * cp, fk[1] -= dy * cp, fk[2] -= dz * cp;
    }
    benchmark::DoNotOptimize(f.data());
  }
  state.counters["atom_steps_per_s"] =
      benchmark::Counter(static_cast<double>(nb.nlocal) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["pairs_per_atom"] = static_cast<double>(pi.size()) / nb.nlocal;
}

// The pairs a cluster layout (GROMACS's, 4 atoms a cluster loaded as one vector) would
// evaluate in the same 500-atom box: the fcc cells as clusters, and every pair of clusters
// (and image) whose bounding boxes come within the cut-off (plus the list's skin, range(1)
// in tenths of an Angstrom) as 4 x 4 lanes. Its loop is the layout's gather floor: r^2 of
// every lane, with the j cluster's coordinates as contiguous loads (no gather), the lanes
// within the cut-off counted. Counters: lanes an atom (half, as the half list's
// candidates), the pairs within the cut-off an atom, and their ratio: the work a vector
// kernel over clusters does for each pair it needs, against the half list's.
void BM_ClusterLanes(benchmark::State& state) {
  const int cells = static_cast<int>(state.range(0));
  const System s = make(cells, false);
  mpmx::particles::Atoms at = s.atoms();
  mpmx::md::wrap(at, s.box(), mpmx::particles::Mat3{}, false);
  const double rc = s.potential().cutoff(), rs = rc + 0.1 * static_cast<double>(state.range(1));
  const double L[3] = {s.box().lx, s.box().ly, s.box().lz};  // fcc(): a cube, no tilt
  const int nc = cells * cells * cells;
  // Clusters: the four atoms of each fcc cell (by the lattice's numbering, each taken to
  // the image nearest its cell's first atom), x y z of four lanes.
  std::vector<double> cx(4 * static_cast<std::size_t>(nc)), cy(cx), cz(cx);
  for (std::size_t i = 0; i < at.size(); ++i) {
    const auto l = static_cast<std::size_t>(at.id[i] - 1);
    if (at.id[i] < 1 || l >= cx.size()) {
      state.SkipWithError("atom ids are not the lattice's 1..N");
      return;
    }
    cx[l] = at.x[i], cy[l] = at.y[i], cz[l] = at.z[i];
  }
  for (int c = 0; c < nc; ++c)
    for (int l = 1; l < 4; ++l)
      for (int d = 0; d < 3; ++d) {
        std::vector<double>& v = d == 0 ? cx : d == 1 ? cy : cz;
        v[4 * c + l] -= L[d] * std::round((v[4 * c + l] - v[4 * c]) / L[d]);
      }
  std::vector<double> lo(3 * static_cast<std::size_t>(nc), 1e300), hi(3 * static_cast<std::size_t>(nc), -1e300);
  for (int c = 0; c < nc; ++c)
    for (int l = 0; l < 4; ++l) {
      const double p[3] = {cx[4 * c + l], cy[4 * c + l], cz[4 * c + l]};
      for (int d = 0; d < 3; ++d)
        lo[3 * c + d] = std::min(lo[3 * c + d], p[d]), hi[3 * c + d] = std::max(hi[3 * c + d], p[d]);
    }
  // Cluster pairs (i, j, image shift) within rs by bounding boxes, each unordered pair once
  // (i's own cluster at no shift: its upper triangle).
  struct Pair {
    int i, j;
    double sx, sy, sz;
    bool self;  // a cluster with itself at no shift: its lanes' upper triangle only
  };
  std::vector<Pair> pairs;
  for (int i = 0; i < nc; ++i)
    for (int j = 0; j < nc; ++j)
      for (int u = -1; u <= 1; ++u)
        for (int v = -1; v <= 1; ++v)
          for (int w = -1; w <= 1; ++w) {
            const double sh[3] = {u * L[0], v * L[1], w * L[2]};
            double d2 = 0;
            for (int d = 0; d < 3; ++d) {
              const double gap =
                  std::max({0.0, lo[3 * i + d] - (hi[3 * j + d] + sh[d]), lo[3 * j + d] + sh[d] - hi[3 * i + d]});
              d2 += gap * gap;
            }
            const bool self = i == j && u == 0 && v == 0 && w == 0;
            // each unordered (i, j, shift) once, as the half list keeps it
            const bool once = j > i || (j == i && mpmx::particles::positive_shift(u, v, w));
            if (d2 < rs * rs && (once || self)) pairs.push_back({i, j, sh[0], sh[1], sh[2], self});
          }
  const double cutsq = rc * rc;
  double within = 0;
  for (auto _ : state) {
    int n = 0;
    for (const Pair& p : pairs) {
      const double* xj = &cx[4 * static_cast<std::size_t>(p.j)];
      const double* yj = &cy[4 * static_cast<std::size_t>(p.j)];
      const double* zj = &cz[4 * static_cast<std::size_t>(p.j)];
      for (int li = 0; li < 4; ++li) {
        const double xi = cx[4 * p.i + li] - p.sx, yi = cy[4 * p.i + li] - p.sy, zi = cz[4 * p.i + li] - p.sz;
        for (int lj = 0; lj < 4; ++lj) {
          const double dx = xi - xj[lj], dy = yi - yj[lj], dz = zi - zj[lj];
          n += (dx * dx + dy * dy + dz * dz < cutsq) & (!p.self | (lj > li));
        }
      }
    }
    within = n;
    benchmark::DoNotOptimize(n);
  }
  const double atoms = static_cast<double>(at.size());
  state.counters["atom_steps_per_s"] = benchmark::Counter(atoms * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["lanes_per_atom"] = 16.0 * static_cast<double>(pairs.size()) / atoms;
  state.counters["pairs_per_atom"] = within / atoms;
  state.counters["lanes_per_pair"] = 16.0 * static_cast<double>(pairs.size()) / within;
}
}  // namespace

BENCHMARK(BM_GatherFloor)->Arg(5)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ScatterFloor)->Arg(5)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ClusterLanes)
    ->ArgNames({"cells", "skin_tenths"})
    ->Args({5, 0})
    ->Args({5, 10})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NeighborBuild)->Arg(5)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NeighborBuild)
    ->ArgNames({"cells", "path"})
    ->ArgsProduct({{5, 6, 7, 8, 9}, {1, 2}})
    ->Args({20, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NeighborBuildCompressed)
    ->ArgNames({"cells", "path"})
    ->ArgsProduct({{5, 6, 7}, {1, 2}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MdStep)->Args({5, 0})->Args({5, 1})->Args({20, 0})->Args({20, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MdStepBcc)->Args({6, 0})->Args({25, 0})->Args({20, 1})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
