// `mpmx run DECK --out DIR` and `mpmx check DECK`.
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/app/commands.hpp"
#include "mpmx/io/mpm_deck.hpp"
#include "mpmx/mpm/run.hpp"

namespace mpmx::app {

void add_mpm_commands(CLI::App& app) {
  struct Args {
    std::string deck, out;
    bool quiet = false, no_plot = false;
  };
  auto args = std::make_shared<Args>();

  CLI::App* run = app.add_subcommand("run", "run a continuum deck");
  run->add_option("deck", args->deck, "TOML deck")->required()->check(CLI::ExistingFile);
  run->add_option("--out,-o", args->out, "output directory (default runs/<deck name>)");
  run->add_flag("--quiet,-q", args->quiet, "no progress line");
  run->add_flag("--no-plot", args->no_plot, "do not draw figures");
  run->callback([args] {
    const auto cfg = io::read_mpm_deck(args->deck);
    const std::string out =
        args->out.empty() ? "runs/" + std::filesystem::path(args->deck).stem().string() : args->out;
    mpm::RunOptions o;
    o.out_dir = out;
    o.quiet = args->quiet;
    o.plot = !args->no_plot;
    const auto r = mpm::run_mpm(cfg, o);
    fmt::print("{}: {} steps in {:.3f} s -> {}/run.json\n", cfg.id, r.steps, r.wall_seconds, out);
    for (const auto& [f, e] : r.errors)
      fmt::print("  error {:<12} l1 {:.3e}  l2 {:.3e}  peak {:.3e}\n", f, e.l1, e.l2, e.peak);
  });

  CLI::App* check = app.add_subcommand("check", "validate a continuum deck without running it");
  check->add_option("deck", args->deck, "TOML deck")->required()->check(CLI::ExistingFile);
  check->callback([args] {
    const auto cfg = io::read_mpm_deck(args->deck);
    fmt::print("{}: ok (case {}, {} cells x {} particles, {} steps, scheme {})\n", args->deck,
               cfg.id, cfg.cells, cfg.per_cell, cfg.steps(), mpm::scheme_name(cfg.scheme.scheme));
  });
}

}  // namespace mpmx::app
