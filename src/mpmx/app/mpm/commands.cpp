// `mpmx run DECK --out DIR` and `mpmx check DECK`.
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpmx/io/run_manifest.hpp"
#include "mpmx/app/cli_checks.hpp"
#include "mpmx/app/deck_kind.hpp"
#include "mpmx/app/commands.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/describe.hpp"
#include "mpmx/app/mpm/step_notes.hpp"
#include "mpmx/app/mpm/preflight.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/app/mpm/unit_slips.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// The energy balance's error past which a run ends with a warning: 5% of the energy in
// play (the shipped decks: 0.01-2% for the smooth problems, 5-16% for strong shocks on
// coarse grids and large deformations, whose transfers dissipate that much).
constexpr double kEnergyBalanceTolerance = 0.05;

// Under mpirun every rank runs the same deck into the same folder: ranks given different
// decks would disagree on the points later (an MPI message of the wrong size). Each rank
// compares the hash of its deck's text and its --out with the others'; the lowest rank
// that differs from the largest names itself, on every rank (exit 2, nothing written).
void same_deck_on_every_rank(const std::string& deck, const std::string& out) {
  if (ranks::size() <= 1) return;
  ranks::together([&] {
    std::ifstream in(deck, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const double mine = static_cast<double>(io::text_hash(text.str() + '\0' + out) >> 11);  // exact in a double
    const auto most = ranks::max({mine, -mine});
    if (most[0] != -most[1] && mine != most[0])
      throw InputError(fmt::format("its deck ({}) or --out ({}) differs from another rank's: under mpirun every "
                                   "rank runs the same deck into the same folder",
                                   deck, out));
  }, ranks::Wait::input);
}

// `mpmx check` of a continuum deck, and `run --check`: the deck read, its memory refused
// when it cannot fit, its work estimate said.
void check_continuum(const std::string& deck, bool force, int ranks) {
  const auto cfg = read_mpm_deck(deck);
  // A check refuses what cannot run here (memory); work over a day is said, not refused:
  // the deck may be meant for a cluster, and `run` asks for --force itself.
  const MpmPreflight pre = preflight_mpm(cfg, ranks, physical_memory_bytes(), true);
  const MpmBudget& budget = pre.budget;
  const std::string steps =
      cfg.cfl_dt ? fmt::format("about {} (dt from the CFL condition at the start)", cfg.steps())
                 : fmt::format("{}", cfg.steps());
  if (cfg.dim == 1) {
    fmt::print("{}: ok (case {}, {} cells x {} particles, {} steps, scheme {})\n", deck, cfg.id, cfg.cells,
               cfg.per_cell, steps, mpm::scheme_name(cfg.scheme.scheme));
  } else {
    std::vector<int> cells(cfg.cells_all.begin(), cfg.cells_all.begin() + cfg.dim),
        per(cfg.per_cell_all.begin(), cfg.per_cell_all.begin() + cfg.dim);
    const std::size_t nb = cfg.bodies.size();
    const std::string bodies = nb == 0   ? std::string("no [[body]]: the grid filled")
                               : nb == 1 ? std::string("1 body")
                                         : fmt::format("{} bodies", nb);
    fmt::print("{}: ok (case {}, {}-D, {} cells, {} points per cell, {}, {} steps, scheme {}, material {})\n", deck,
               cfg.id, cfg.dim, fmt::join(cells, " x "), fmt::join(per, " x "), bodies, steps,
               mpm::scheme_name(cfg.scheme.scheme), cfg.material.model);
  }
  fmt::print("  estimate: about {} of memory, {:.3g} hours of work on one core{}{}{}\n", format_bytes(budget.bytes),
             budget.seconds / 3600.0,
             budget.levels > 1 ? fmt::format(" (a study of {} grids: the finest grid's memory, the work of all)",
                                             budget.levels)
                               : std::string(),
             budget.md_atoms > 0 ? fmt::format(", {:.4g} MD atoms", budget.md_atoms) : std::string(),
             budget.ranks > 1 ? fmt::format(" (each of {} ranks)", budget.ranks) : std::string());
  fmt::print("  the continuum at {:.3g} point-steps/s per core ({})\n", budget.point_rate,
             budget.point_rate_measured ? "its scheme and law timed on this core just now"
                                        : "a typical figure");
  if (budget.md_atom_steps > 0)
    fmt::print("  {:.0f} points x {} atoms: {:.3g} MD atom-steps, {:.3g} core-hours at {:.3g} atom-steps/s per core "
               "({}), with one box per point: the most it can cost (boxes shared by history run fewer, as "
               "run.json's md.atom_steps against md.atom_steps_unshared says; the memory is that of one box per "
               "point too)\n",
               budget.points, budget.md_atoms_per_point, budget.md_atom_steps,
               budget.md_atom_steps / budget.md_rate / 3600.0, budget.md_rate,
               budget.md_rate_measured ? "one of its boxes timed on this core just now" : "a typical figure");
  if (budget.md_atom_steps > 0)
    fmt::print("  each box keeps {:.0f} bytes per atom between macro steps (its atoms and its neighbour list)\n",
               budget.md_bytes_per_atom);
  if (cfg.material.spec)
    for (const std::string& line : cfg.material.spec->check_notes()) fmt::print("  {}\n", line);
  for (const std::string& line : describe_pistons_and_gauges(cfg)) fmt::print("  {}\n", line);
  for (const std::string& line : describe_time_step(cfg)) fmt::print("  {}\n", line);
  if (!pre.pending.empty()) fmt::print("  {}\n", pre.pending);
  for (const std::string& slip : unit_slips(cfg)) fmt::print("  warning: {}\n", slip);
  if (!(budget.seconds <= kWorkLimitSeconds) && !force)
    fmt::print("  more than a day of work{}: `mpmx run` needs --force; over N MPI ranks it is about 1/N "
               "(check --ranks N)\n",
               budget.ranks > 1 ? " on each rank" : " on one core");
}

}  // namespace

void add_mpm_commands(CLI::App& app) {
  struct Args {
    std::string deck, out;
    bool quiet = false, no_plot = false, resume = false, check = false, force = false, overwrite = false;
    int threads = 0, ranks = 1;
    std::int64_t checkpoint_every = 0, stop_after = 0;
    double checkpoint_minutes = 10.0, rebalance_above = 1.2;
  };
  auto args = std::make_shared<Args>();

  CLI::App* run = app.add_subcommand("run", "run a continuum deck");
  // The deck reader says what is wrong with the path (CLI11's ExistingFile says "does not
  // exist" of a path too long to look up).
  run->add_option("deck", args->deck, "TOML deck")->required();
  run->add_option("--out,-o", args->out, "output directory (default runs/<deck name>)");
  run->add_flag("--quiet,-q", args->quiet, "no progress line");
  run->add_flag("--no-plot", args->no_plot, "do not draw figures");
  run->add_option("--threads,-j", args->threads,
                  "threads for the whole step: md_closure's MD boxes and, in runs of 8192 points or more, every "
                  "material law, the grid and the points; the same results for any N (default 0: the MD boxes "
                  "on all cores, the rest on one)")
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--check", args->check, "only check the deck and print its estimate, as `mpmx check`; write nothing");
  run->add_flag("--force", args->force, "run even when the work estimate exceeds about a day (never the memory one)");
  run->add_flag("--resume", args->resume,
                "continue from OUT/checkpoint.bin (bit-for-bit; refused when the deck or a file it reads changed "
                "since)");
  run->add_flag("--overwrite", args->overwrite, kOverwriteHelp);
  run->add_option("--checkpoint-every", args->checkpoint_every, "write OUT/checkpoint.bin every N steps")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--checkpoint-minutes", args->checkpoint_minutes,
                  "write OUT/checkpoint.bin every so many minutes of wall time (0: only on Ctrl-C; default 10)")
      ->check(CLI::NonNegativeNumber);
  run->add_option("--rebalance-above", args->rebalance_above,
                  "under MPI, move MD boxes between ranks at a checkpoint when the slowest rank's MD time "
                  "exceeds this many times the mean (default 1.2; 0: at every checkpoint)")
      ->check(finite_non_negative());
  // For tests: stop as if interrupted after step N (a checkpoint at a known step).
  run->add_option("--stop-after", args->stop_after, "")->group("")->check(CLI::NonNegativeNumber);
  run->callback([args, run] {
    if (args->check) {
      if (ranks::size() > 1) {  // every rank would print the same check
        ranks::mark_agreed();   // the same command line on every rank
        throw InputError("run --check runs as one process: without mpirun, or `mpmx check --ranks N DECK` for the "
                         "estimate over N ranks");
      }
      require_deck_kind(args->deck, DeckKind::continuum);
      say_ignored_by_check(*run);
      return check_continuum(args->deck, args->force, 1);
    }
    // Every rank reads the deck and its estimate; under MPI a bad one stops them all with
    // one message.
    MpmConfig cfg;
    ranks::together([&] {
      require_deck_kind(args->deck, DeckKind::continuum);
      cfg = read_mpm_deck(args->deck);
      preflight_mpm_run(cfg, ranks::size(), physical_memory_bytes(), args->force);
    }, ranks::Wait::input);
    const std::string out = out_dir_of(args->out, args->deck);
    same_deck_on_every_rank(args->deck, out);
    RunOptions o;
    o.out_dir = out;
    o.quiet = args->quiet;
    o.plot = !args->no_plot;
    o.threads = run_threads_of(args->threads);
    o.resume = args->resume;
    o.owner = {io::run_owner("run", args->deck), args->overwrite};
    o.checkpoint_every = args->checkpoint_every;
    o.stop_after = args->stop_after;
    o.rebalance_above = args->rebalance_above;
    o.checkpoint_seconds = 60.0 * args->checkpoint_minutes;
    const auto r = run_any(cfg, o);
    if (r.interrupted) {
      ranks::mark_agreed();  // every rank stopped at the same step
      if (cfg.convergence_levels > 1)  // its levels write under OUT/level_K and do not resume
        throw Interrupted(fmt::format("a convergence study stopped in one of its {} levels, at step {}; it does not "
                                      "resume: run it afresh (mpmx run {} --out {} --overwrite)",
                                      cfg.convergence_levels, r.steps, args->deck, out));
      // dt = "cfl": the step count is not known ahead (the first step's would mislead), the time is.
      const std::string where = cfg.cfl_dt ? fmt::format("{} (t = {:.6g} of {})", r.steps, r.time, cfg.end)
                                           : fmt::format("{} of {}", r.steps, cfg.steps());
      throw Interrupted(fmt::format("step {} written to {}; continue with: mpmx run {} --out {} --resume", where,
                                    checkpoint_path(out), args->deck, out));
    }
    if (!ranks::root()) return;
    // After --resume the steps and the time are the whole run's: say this invocation's steps too.
    const std::string now =
        r.steps_now == r.steps ? std::string() : fmt::format(" ({} of them now, after --resume)", r.steps_now);
    fmt::print("{}: {} step{}{} in {:.3f} s -> {}/run.json\n", cfg.id, r.steps, r.steps == 1 ? "" : "s", now,
               r.wall_seconds, out);
    if (!r.time_steps.empty()) fmt::print("  time: {}\n", r.time_steps);
    for (const auto& [f, e] : r.errors)
      fmt::print("  error {:<12} l1 {:.3e}  l2 {:.3e}  peak {:.3e}\n", f, e.l1, e.l2, e.peak);
    for (const auto& [f, order] : r.convergence_order)
      fmt::print("  observed order {:<12} {:.2f} (L2, over {} grids)\n", f, order, cfg.convergence_levels);
    if (r.md_atom_steps > 0)
      fmt::print("  MD: {:.4g} atom-steps, {:.4g} atom-steps/s on {} thread(s){}\n",
                 static_cast<double>(r.md_atom_steps), r.md_atom_steps / r.wall_seconds, r.threads,
                 r.ranks > 1 ? fmt::format(" x {} ranks (imbalance {:.3f})", r.ranks, r.rank_imbalance) : "");
    if (std::isfinite(r.stress_vs_direct_md))
      fmt::print("  stress vs direct MD (eq. 7.12): {:.2f}%\n", 100.0 * r.stress_vs_direct_md);
    if (std::isfinite(r.energy_growth))
      fmt::print("  energy: total (kinetic + stored, less the work put in) {:+.3f}% of its scale{}\n",
                 100.0 * r.energy_growth, r.energy_grew ? " (past time.energy_growth: status energy_growth)" : "");
    // The balance every law has (a law without an energy account of its own included):
    // past the tolerance the user hears of it, whatever else the run printed.
    if (r.energy_balance_error > kEnergyBalanceTolerance)
      fmt::print("  warning: the kinetic energy's change misses the work of the stresses and the boundaries by "
                 "{:.1f}% of the energy in play (run.json's conservation.energy.relative_error; the tolerance is "
                 "{:.0f}%): the scheme's transfers between points and grid did not conserve it, which a finer grid, "
                 "more points per cell, a smaller time.dt or another scheme lower (docs/guide.md, \"Energy\")\n",
                 100.0 * r.energy_balance_error, 100.0 * kEnergyBalanceTolerance);
  });

  CLI::App* check = app.add_subcommand(
      "check", "validate a deck of any kind (continuum, md, dpd, fit-dpd) and print its estimate, running nothing");
  check->add_option("deck", args->deck, "TOML deck")->required();
  check->add_flag("--force", args->force, "do not mention a work estimate over about a day (memory is always checked)");
  check->add_option("--ranks", args->ranks,
                    "estimate for a run over so many MPI ranks (md_closure boxes spread over them; default 1)")
      ->check(CLI::Range(1, 1 << 20));
  check->add_option("--out,-o", args->out, "ignored: check writes nothing");
  check->add_option("--threads,-j", args->threads, "ignored: check runs nothing");
  check->add_flag("--resume", args->resume, "ignored: check runs nothing");
  check->add_flag("--quiet,-q", args->quiet, "ignored: check draws no progress line");
  check->add_flag("--no-plot", args->no_plot, "ignored: check draws no figures");
  check->add_flag("--check", args->check, "ignored: checking is what check does");
  check->callback([args, check] {
    say_ignored_by_check(*check);
    say_ignored(*check, {{"--check", "checking is what check does"}});
    if (check_deck_of_another_kind(args->deck, args->force)) return;  // md, dpd, fit-dpd: their own check
    check_continuum(args->deck, args->force, args->ranks);
  });
}

}  // namespace mpmx::app
