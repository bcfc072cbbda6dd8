#pragma once
// A whole continuum run: set-up, the step loop, records, comparison with the
// reference, checkpoints, conservation figures, run.json and figures.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "mpmx/io/staged_dir.hpp"
#include "mpmx/app/mpm/comparison.hpp"
#include "mpmx/app/mpm/config.hpp"
#include "mpmx/app/mpm/gauges.hpp"
#include "mpmx/app/run_folder.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

struct RunOptions {
  std::string out_dir;   // "" = write nothing (tests)
  io::FolderOwner owner;  // who writes out_dir: another run's folder is refused unless overwrite (io/staged_dir.hpp)
  bool quiet = false;    // no progress line
  bool plot = true;      // call tools/plot when the deck allows and matplotlib is present
  int threads = 0;       // the whole step (0: the MD boxes on all cores, the rest on one)
  // Checkpoints (need out_dir): OUT/checkpoint.bin every `checkpoint_every` steps, or
  // when `checkpoint_seconds` of wall time passed since the last one (0: never), and
  // on Ctrl-C. `resume` continues from OUT/checkpoint.bin bit-for-bit.
  std::int64_t checkpoint_every = 0;
  double checkpoint_seconds = 600.0;
  bool resume = false;
  // MPI: at each checkpoint, boxes move between ranks when the slowest rank's MD time
  // since the last checkpoint exceeds this x the mean (0: at every checkpoint).
  double rebalance_above = 1.2;
  std::int64_t stop_after = 0;  // stop as if interrupted after this step (tests)
};

template <int Dim>
struct RunResultOf {
  std::int64_t steps = 0;
  std::int64_t steps_now = 0;  // of them, this invocation's (after a resume, fewer)
  double wall_seconds = 0.0;
  std::map<std::string, FieldError> errors;   // by field; also "energy", "front_speed"
  double front_speed = 0.0;                   // shock_front cases
  // Conservation (S4). The scalars are the x components (1-D); the vectors every one.
  double mass_particles = 0.0, mass_nodes = 0.0;
  double momentum_initial = 0.0, momentum_final = 0.0, boundary_impulse = 0.0;
  std::array<double, 3> momentum_initial_vec{}, momentum_final_vec{}, boundary_impulse_vec{};
  double momentum_scale = 0.0;                // max sum m|v| seen at the ends
  double max_force_sum = 0.0;                 // max_steps |sum f| / sum |f|
  double kinetic_initial = 0.0, kinetic_final = 0.0, stress_work = 0.0, boundary_work = 0.0;
  double body_work = 0.0;                     // a manufactured solution's body force's
  double stored_initial = 0.0, stored_final = 0.0;  // the materials' stored energy
  double max_kinetic = 0.0;                   // in the lab or the grid's frame (a piston carries it)
  double stress_vs_direct_md = std::nan("");  // eq. 7.12 over the compared times (direct_md)
  std::int64_t md_atom_steps = 0;             // md_closure: atoms x MD steps, relaxation included
  int threads = 1;                            // per rank
  int ranks = 1;                              // MPI ranks
  double rank_imbalance = 1.0;                // the slowest rank's MD time over the mean
  int rebalances = 0;                         // checkpoints at which boxes moved between ranks
  bool interrupted = false;                   // stopped by Ctrl-C (or stop_after): checkpoint written
  std::string time_steps;                     // dt = "cfl": the steps' summary line (app/mpm/step_log.hpp)
  // The total energy's growth (kinetic + stored less the work put in, over the
  // initial scale) at the end or where the run stopped; NaN where the law keeps no
  // energy account. Past time.energy_growth the run's status is "energy_growth".
  double energy_growth = std::nan("");
  bool energy_grew = false;
  // The [[gauge]]s' histories: their rows where the run wrote no folder (the tables
  // gauge_<name>.csv hold them otherwise).
  std::vector<GaugeTrace> gauges;
  mpm::State<Dim> state;                      // the final state
  double energy_error() const { return std::abs(kinetic_final - kinetic_initial + stress_work - boundary_work); }
  // Its scale, the energy in play: the largest kinetic energy seen (in the lab or in the
  // grid's frame, where a piston is the wall and the bar runs at -u_p onto it: the wall
  // run's scale from the first step), or the boundary's work where larger (half of a
  // piston's work is the bar's kinetic energy, half is stored behind the shock).
  double energy_scale() const { return std::max(max_kinetic, std::abs(boundary_work)); }
  double momentum_error() const {
    double e2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double e = momentum_final_vec[a] - momentum_initial_vec[a] - boundary_impulse_vec[a];
      e2 += e * e;
    }
    return std::sqrt(e2);
  }
};
using RunResult = RunResultOf<1>;

// A run of the deck's dimension.
template <int Dim>
RunResultOf<Dim> run_mpm_dim(const MpmConfig& c, const RunOptions& o);
// 1-D decks (the tests' and the multiscale cases').
RunResult run_mpm(const MpmConfig& c, const RunOptions& o);

// What the CLI reports of a run of any dimension.
struct RunSummary {
  std::int64_t steps = 0;
  std::int64_t steps_now = 0;  // as RunResultOf's
  double wall_seconds = 0.0;
  std::size_t particles = 0;
  bool interrupted = false;
  std::map<std::string, FieldError> errors;
  std::int64_t md_atom_steps = 0;
  int threads = 1, ranks = 1;
  double rank_imbalance = 1.0;
  double stress_vs_direct_md = std::nan("");
  double energy_growth = std::nan("");  // as RunResultOf's
  bool energy_grew = false;
  double energy_balance_error = 0.0;    // run.json's conservation.energy.relative_error
  std::map<std::string, double> convergence_order;  // a convergence study's L2 order by field
  std::string time_steps;                           // as RunResultOf's
  double time = 0.0;                                // where the run ended (stopped)
};
// Runs a deck of any dimension (a convergence study when convergence.levels > 1).
RunSummary run_any(const MpmConfig& c, const RunOptions& o);

}  // namespace mpmx::app
