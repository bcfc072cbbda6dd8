#include "mpmx/app/mpm/budget.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/md/budget.hpp"
#include "mpmx/app/mpm/bodies.hpp"
#include "mpmx/app/mpm/convergence.hpp"
#include "mpmx/app/mpm/point_rate.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// Bytes, fitted to the peak RSS of `mpmx run` (Release; a 3-D ddmp bar of 40^3 cells and
// 512,000 points peaked at 1.44 GiB, estimated 1.7 GiB; docs/reliability.md): per point
// its arrays (position, velocity, mass, volumes, domain, strain, stress, gradient,
// viscous stress: 2D + 4 + 5 D^2 doubles) and its stencil (up to 4^D nodes, a weight,
// D gradients and an index each, per sub-point), per node its fields (mass, momentum,
// velocities, force: 4 + 6 D doubles) and the small-mass maps; the program 10 MiB (8.5 MB
// measured for a 1-D run).
constexpr double kBytesFixed = 10.0 * 1024 * 1024;
constexpr double kOverhead = 1.25;  // measured peak over the sum of the arrays (scratch, copies)

double point_bytes(int dim, double subpoints) {
  const double arrays = 8.0 * (2 * dim + 4 + 5 * dim * dim);
  const double stencil = std::pow(4.0, dim) * (8.0 * (1 + dim) + 4.0);
  return kOverhead * (arrays + stencil * subpoints);
}
double node_bytes(int dim) { return kOverhead * 8.0 * (4 + 6 * dim); }

// One grid's figures; `cost` the law's per point (timed once for every level of a study),
// `rate` the continuum's point-steps a second (0: the typical figure).
MpmBudget estimate_level(const MpmConfig& c, int ranks, const material::PointCost& cost, double rate) {
  MpmBudget b;
  b.deck = c.deck_path;
  b.ranks = ranks > 1 ? ranks : 1;
  const int dim = c.dim;
  b.points = 1, b.nodes = 1;
  for (int d = 0; d < dim; ++d) {
    const double cells = dim == 1 ? c.cells : c.cells_all[d];
    const double per = dim == 1 ? c.per_cell : c.per_cell_all[d];
    b.points *= cells * per;
    b.nodes *= cells + 1;
  }
  // A deck of bodies fills part of the grid: count its points where that is cheap.
  if (!c.bodies.empty() && b.points <= 1e7) b.points = static_cast<double>(count_points(c));
  if (c.scheme.scheme == Scheme::ddmp_subpoints) {
    if (dim == 1) b.subpoints = c.scheme.subpoints;
    else
      for (int d = 0; d < dim; ++d) b.subpoints *= c.scheme.subpoints_axes[d];
  }
  b.steps = c.cfl_dt ? (c.dt > 0 ? c.end / c.dt : 0.0) : static_cast<double>(c.steps());
  const double pb = point_bytes(dim, b.subpoints) * b.points, nb = node_bytes(dim) * b.nodes;
  b.bytes = kBytesFixed + pb + nb;
  b.size_key = pb >= nb ? (b.subpoints > 1 ? "particles.per_cell and scheme.subpoints" : "particles.per_cell and grid.cells")
                        : "grid.cells";
  b.point_rate_measured = rate > 0;
  b.point_rate = rate > 0 ? rate : (dim == 1 ? kPointSteps1dPerSecond : kPointStepsPerSecond);
  b.seconds = b.points * b.subpoints * b.steps / b.point_rate;
  // A law with a model inside every point (md_closure's boxes): its atoms, memory and work.
  if (cost.atoms > 0) {
    b.md_atoms_per_point = cost.atoms;
    b.md_atoms = b.points * cost.atoms;
    b.md_bytes_per_atom = cost.bytes / cost.atoms;
    const double mb = cost.bytes * std::ceil(b.points / b.ranks) + cost.scratch_bytes * hardware_threads();
    b.bytes += mb;
    if (mb > pb && mb > nb) b.size_key = cost.size_key;
    b.md_atom_steps = b.md_atoms * (cost.steps_per_step * b.steps + cost.setup_steps);
    b.md_rate = cost.atom_steps_per_second > 0 ? cost.atom_steps_per_second : md::kMdAtomStepsPerSecond;
    b.md_rate_measured = cost.atom_steps_per_second > 0;
    b.seconds += b.md_atom_steps / b.md_rate / b.ranks;
  }
  return b;
}

// Every grid of the deck: one, or a convergence study's levels.
MpmBudget estimate_levels(const MpmConfig& c, int ranks, const material::PointCost& cost, double rate) {
  if (c.convergence_levels <= 1) return estimate_level(c, ranks, cost, rate);
  // A study runs its levels one after another: its memory is the finest grid's, its work
  // that of every level together (each has 2^D times the points of the one before and
  // twice the steps).
  const int last = c.convergence_levels - 1;
  MpmBudget b;
  double seconds = 0, atom_steps = 0;
  for (int k = 0; k <= last; ++k) {
    material::PointCost ck = cost;
    ck.steps_per_step = std::max(1.0, cost.steps_per_step / (1 << k));  // time.dt / 2^k over material.md.dt
    b = estimate_level(refined(c, k), ranks, ck, rate);
    seconds += b.seconds, atom_steps += b.md_atom_steps;
  }
  b.seconds = seconds, b.md_atom_steps = atom_steps;
  b.levels = c.convergence_levels;
  b.size_key = fmt::format("convergence.levels = {} (its finest grid, {} times grid.cells along each axis; {})",
                           c.convergence_levels, 1 << last, b.size_key);
  b.work_key = "convergence.levels, time.end / time.dt";
  return b;
}

}  // namespace

MpmBudget estimate_mpm(const MpmConfig& c, int ranks) {
  const material::PointCost cost = c.material.spec ? c.material.spec->point_cost(c.dt) : material::PointCost{};
  MpmBudget b = estimate_levels(c, ranks, cost, 0.0);
  // The continuum's own work long enough to matter: timed for this deck on this machine.
  // Not for a deck the memory check refuses anyway: timing builds a copy of it.
  const double continuum = b.seconds - b.md_atom_steps / std::max(b.md_rate, 1.0) / b.ranks;
  const double memory = static_cast<double>(physical_memory_bytes());
  if (continuum > kTimeRateAboveSeconds && (memory <= 0 || b.bytes <= memory)) {
    const MpmBudget l0 = c.convergence_levels > 1 ? estimate_level(c, ranks, cost, 0.0) : b;  // the deck's grid
    if (const double rate = measure_point_steps_per_second(c, l0.points, l0.subpoints, l0.nodes); rate > 0)
      b = estimate_levels(c, ranks, cost, rate);
  }
  // A law's work before the points are built (md_closure's NPT box): once, on every rank.
  if (cost.prepare_atom_steps > 0) {
    b.md_atom_steps += cost.prepare_atom_steps;
    b.seconds += cost.prepare_atom_steps / std::max(b.md_rate, 1.0);
  }
  return b;
}

void check_mpm_budget(const MpmBudget& b, std::uint64_t memory_bytes, bool force) {
  if (memory_bytes > 0 && !(b.bytes <= static_cast<double>(memory_bytes)))
    throw InputError(fmt::format(
        "{}{}: {:.4g} points{}, {:.4g} grid nodes{} need about {} of memory ({:.4g} bytes){}, more than this "
        "machine's {}: make the deck smaller{}",
        b.deck.empty() ? std::string() : b.deck + ": ", b.size_key, b.points,
        b.subpoints > 1 ? fmt::format(" of {:.4g} sub-points each", b.subpoints) : std::string(), b.nodes,
        b.md_atoms > 0 ? fmt::format(" and {:.4g} MD atoms", b.md_atoms) : std::string(), format_bytes(b.bytes),
        b.bytes, b.ranks > 1 ? fmt::format(" on each of {} ranks", b.ranks) : std::string(),
        format_bytes(static_cast<double>(memory_bytes)),
        b.md_atoms > 0 ? fmt::format(", or spread its MD boxes over MPI ranks (mpirun -np N mpmx run ...; "
                                     "`mpmx check --ranks N {}` prints one rank's share)",
                                     b.deck.empty() ? "DECK" : b.deck)
                       : std::string()));
  if (!force && !(b.seconds <= kWorkLimitSeconds))
    throw InputError(fmt::format(
        "{}: {:.4g} points x {:.4g} steps{}{}, about {:.3g} days of work: more than the day a run takes without "
        "--force",
        b.work_key, b.points * b.subpoints, b.steps,
        b.levels > 1 ? fmt::format(" on the finest of {} grids (all of them together)", b.levels) : std::string(), b.md_atoms > 0 ? fmt::format(" with {:.4g} MD atoms", b.md_atoms) : "",
        b.seconds / 86400.0));
}

}  // namespace mpmx::app
