// Micro-benchmarks of the MD engine: ten leapfrog steps of fcc Cu (Cu_mishin1) at 500
// and 32,000 atoms, double and mixed precision, beside bcc Fe (Fe_mm, a = 2.8553) at 432
// and 31,250 atoms along [100] and 32,000 along [110] (M6: the new lattices at the engine's
// rate, atom_steps_per_s of each in one invocation); and one neighbour-list build of the same
// crystals (skin 1 A), whose cost against a step's is what a box that rebuilds often
// (a multiscale box under shear and shock) pays.
#include <benchmark/benchmark.h>

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

void BM_NeighborBuild(benchmark::State& state) {
  const System s = make(static_cast<int>(state.range(0)), false);
  Neighbors nb;
  for (auto _ : state) {
    nb.build(s.atoms(), s.box(), s.potential().cutoff(), 1.0);
    benchmark::DoNotOptimize(nb.list.data());
  }
  state.counters["atoms_per_s"] =
      benchmark::Counter(static_cast<double>(s.atoms().size()) * state.iterations(), benchmark::Counter::kIsRate);
  state.counters["pairs_per_atom"] = static_cast<double>(nb.list.size()) / s.atoms().size();
}
}  // namespace

BENCHMARK(BM_NeighborBuild)->Arg(5)->Arg(20)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MdStep)->Args({5, 0})->Args({5, 1})->Args({20, 0})->Args({20, 1})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MdStepBcc)->Args({6, 0})->Args({25, 0})->Args({20, 1})->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
