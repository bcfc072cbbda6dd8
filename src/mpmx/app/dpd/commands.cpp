// `mpmx dpd DECK --out DIR [--threads N] [--check] [--quiet] [--still]`: a DPD(E)-only run
// (seed 004 sec. 2.2; issue 16); `mpmx fit-dpd DECK --out DIR [--threads N] [--check]`:
// the MD-to-DPD fit of D0.
#include <filesystem>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/io/run_manifest.hpp"
#include "mpmx/app/cli_checks.hpp"
#include "mpmx/app/deck_kind.hpp"
#include "mpmx/app/commands.hpp"
#include "mpmx/app/dpd/budget.hpp"
#include "mpmx/app/dpd/config.hpp"
#include "mpmx/app/dpd/fit_run.hpp"
#include "mpmx/app/dpd/fit_stop.hpp"
#include "mpmx/app/dpd/preflight.hpp"
#include "mpmx/app/dpd/run.hpp"
#include "mpmx/app/run_folder.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/io/plot.hpp"
#include "mpmx/io/staged_dir.hpp"
#include "mpmx/multiscale/dpd_mpm.hpp"

namespace mpmx::app {

namespace {

// `dpd --check`, and `mpmx check` of a DPD deck: what the run checks before its work,
// and its work estimate.
void check_dpd(const std::string& path, bool force) {
  auto deck = io::Deck::from_file(path);
  const dpd::DpdConfig config = dpd::read_dpd_config(deck);
  const dpd::DpdBudget budget = dpd::preflight_dpd(config, force);  // check refuses what the run would
  fmt::print("{}: ok (dpd deck); {:.4g} particles, {:.4g} particle-steps ({}), about {} on one core at {:.3g} "
             "particle-steps/s ({})\n",
             path, budget.particles, budget.particle_steps, budget.work_key, format_duration(budget.seconds()),
             budget.rate,
             budget.rate_measured ? "its system timed on this core just now" : "a typical figure");
}

// `fit-dpd --check`, and `mpmx check` of a fit deck.
void check_fit(const std::string& path, bool) {
  auto deck = io::Deck::from_file(path);
  (void)dpd::read_fit_config(deck);
  fmt::print("{}: ok (fit-dpd deck)\n", path);
}

}  // namespace

void add_dpd_commands(CLI::App& app) {
  register_deck_check(DeckKind::dpd, check_dpd);
  register_deck_check(DeckKind::fit_dpd, check_fit);
  auto* dpd = app.add_subcommand("dpd", "Run a DPD / DPDE mesoparticle deck (Shardlow or velocity Verlet)");
  struct Args {
    std::string deck, out;
    int threads = 0;  // all cores, as run and md
    bool check = false, quiet = false, no_plot = false, still = false, force = false, resume = false, overwrite = false;
    std::int64_t stop_after = 0;
  };
  auto args = std::make_shared<Args>();
  dpd->add_option("deck", args->deck, "DPD deck (TOML)")->required();
  dpd->add_option("--out,-o", args->out, "output directory (default runs/<deck name>, as run)");
  dpd->add_option("--threads,-j", args->threads,
                  "OpenMP threads (default: all cores, as run and md; results are the same for any count)");
  dpd->add_flag("--check", args->check, "validate the deck, print its work estimate and exit");
  dpd->add_flag("--force", args->force, "run even when the work estimate exceeds about a day");
  dpd->add_flag("--quiet,-q", args->quiet, "no progress line");
  dpd->add_flag("--overwrite", args->overwrite, kOverwriteHelp);
  dpd->add_flag("--resume", args->resume,
                "continue from OUT/checkpoint.bin, written by Ctrl-C or SIGTERM at a record (bit-for-bit; refused when "
                "the deck or a file it reads changed since)");
  // For tests: stop as if interrupted at the first record at or past step N.
  dpd->add_option("--stop-after", args->stop_after, "")->group("")->check(CLI::NonNegativeNumber);
  dpd->add_flag("--no-plot", args->no_plot, "no figures (tools/plot/dpd_study.py) after the run");
  dpd->add_flag("--still", args->still,
                "the rigid groups (flyer, grips) start at rest: the undriven twin of the run, which "
                "tools/plot/dpd_study.py subtracts to leave the wave alone");
  dpd->callback([args, dpd] {
    require_deck_kind(args->deck, DeckKind::dpd);
    if (args->check) {
      say_ignored_by_check(*dpd);
      return check_dpd(args->deck, args->force);
    }
    auto deck = io::Deck::from_file(args->deck);
    dpd::DpdConfig config = dpd::read_dpd_config(deck);
    config.still = args->still;
    dpd::preflight_dpd(config, args->force);  // what --check refuses, the run refuses
    const std::string out = out_dir_of(args->out, args->deck);
    const int threads = threads_of(args->threads);
    RunControlOptions o;
    o.quiet = args->quiet;
    o.resume = args->resume;
    o.stop_after = args->stop_after;
    o.out = out;
    const auto r = run_resumable(out, args->resume, {io::run_owner("dpd", args->deck), args->overwrite},
                                 [&](const std::string& dir) {
      return dpd::run_dpd(config, dir, deck.table(), threads, o,
                          multiscale::dpd_mpm_mover(config.grid, config.continuum, config.potential, threads));
    });
    if (r.interrupted)
      throw Interrupted(fmt::format("step {} of {} written to {}; continue with: mpmx dpd {} --out {} --resume{}",
                                    r.step, r.last_step, checkpoint_path(out), args->deck, out,
                                    args->still ? " --still" : ""));
    fmt::print("{} particles, {} steps, {:.3g} s, {:.4g} particle-steps/s, mean T {:.2f} K -> {}/run.json\n",
               r.particles, r.steps, r.wall_seconds, r.particle_steps_per_second, r.temperature, out);
    if (config.analysis.records() && !args->no_plot && io::matplotlib_present())
      io::run_plot_script("dpd_study.py", fmt::format("--out '{0}' '{0}' >/dev/null", out));
  });

  auto* fit = app.add_subcommand("fit-dpd", "Fit a DPD pair potential to an MD isotherm (D0: MD to DPD)");
  auto fargs = std::make_shared<Args>();
  fit->add_option("deck", fargs->deck, "fit deck (TOML)")->required();
  fit->add_option("--out,-o", fargs->out, "output directory (default runs/<deck name>, as run)");
  fit->add_option("--threads,-j", fargs->threads, "threads over the densities (default: all cores)");
  fit->add_flag("--check", fargs->check, "validate the deck and exit");
  fit->add_flag("--quiet,-q", fargs->quiet, "no progress line");
  fit->add_flag("--no-plot", fargs->no_plot, "ignored: fit-dpd draws no figures (accepted as every command takes it)");
  fit->add_flag("--overwrite", fargs->overwrite, kOverwriteHelp);
  fit->add_flag("--resume", fargs->resume,
                "continue a stopped fit from OUT/checkpoint.bin (its last finished stage; bit-for-bit; refused when "
                "the deck or a file it reads changed since)");
  // For tests: stop as if interrupted once so many stages are finished.
  fit->add_option("--stop-after", fargs->stop_after, "")->group("")->check(CLI::NonNegativeNumber);
  fit->callback([fargs, fit] {
    require_deck_kind(fargs->deck, DeckKind::fit_dpd);
    if (fargs->check) {
      say_ignored_by_check(*fit);
      return check_fit(fargs->deck, false);
    }
    say_ignored(*fit, {{"--no-plot", "fit-dpd draws no figures"}});
    auto deck = io::Deck::from_file(fargs->deck);
    const dpd::FitConfig config = dpd::read_fit_config(deck);
    const std::string out = out_dir_of(fargs->out, fargs->deck);
    const int threads = threads_of(fargs->threads);
    std::ostringstream text;
    text << deck.table();
    const std::string checkpoint = (std::filesystem::path(out) / "checkpoint.bin").string();
    dpd::FitProgress from;
    if (fargs->resume) {
      if (!std::filesystem::exists(checkpoint))
        throw InputError(fmt::format("no checkpoint to resume from: {} does not exist", checkpoint));
      from = dpd::read_fit_checkpoint(checkpoint, text.str(), config.density_ratios.size());
    }
    const io::FolderOwner owner{io::run_owner("fit-dpd", fargs->deck), fargs->overwrite};
    const auto r = io::run_staged(
        out,
        [&](const std::string& dir) {
          // Stops the fit at once, saving the stages it finished.
          dpd::FitStop on_signal(fargs->deck, out, deck.table(), text.str(), config.density_ratios.size(), owner.run);
          return dpd::run_fit(config, dir, deck.table(), threads, fargs->quiet, from, [&](const dpd::FitProgress& p) {
            on_signal.keep(p);
            if (fargs->stop_after > 0 && p.stages() >= fargs->stop_after) on_signal.stop();
          });
        },
        owner);
    std::error_code ec;
    std::filesystem::remove(checkpoint, ec);  // the fit is whole: nothing to resume
    fmt::print("morse D0 = {:.6g} eV, alpha = {:.6g} 1/A, r0 = {:.6g} A, rc = {} A; max |P_DPDE - P_MD| = {:.3g} of "
               "the MD range; zero-pressure rho/rho0 MD {:.5f} DPDE {:.5f}; {:.3g} s -> {}/{}\n",
               r.potential.d0, r.potential.alpha, r.potential.r0, r.potential.rc, r.max_deviation_over_range,
               r.zero_pressure_md, r.zero_pressure_dpd, r.wall_seconds, out, config.potential_file);
    if (r.elastic)
      fmt::print("C11 and C12 of the model at {:g} K against the MD crystal's: {:+.2f}%, {:+.2f}% (run.json elastic)\n",
                 config.md.temperature, 100 * r.c11_residual, 100 * r.c12_residual);
  });
}

}  // namespace mpmx::app
