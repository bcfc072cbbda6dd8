// `mpmx md DECK --out DIR [--check] [--force] [--lammps [--ranks N] | --lammps-write-only]`:
// an MD-only run (issue 3); for a bar deck, optionally its reference through LAMMPS.
// `--check` does every validation the run does (deck, potential file and its elements,
// memory and work estimates) and writes nothing; the run creates DIR only after them.
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/app/cli_checks.hpp"
#include "mpmx/app/commands.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/io/staged_dir.hpp"
#include "mpmx/md/bar.hpp"
#include "mpmx/md/budget.hpp"
#include "mpmx/md/config.hpp"
#include "mpmx/md/lammps_bar.hpp"
#include "mpmx/md/run.hpp"

namespace mpmx::app {

namespace {

// The bar of a deck through LAMMPS instead of mpmx's own MD: inputs in OUT/lammps/,
// then (unless write_only) lmp, and its slab stress as OUT/bar_stress_lammps.csv.
void run_bar_lammps(const std::string& deck, const md::MdConfig& c, const std::string& out, bool write_only,
                    int ranks) {
  namespace fs = std::filesystem;
  if (!c.bar)
    throw InputError(fmt::format("{}: --lammps and --lammps-write-only need a deck with a [bar] table", deck));
  const fs::path dir = fs::path(out) / "lammps";
  const md::Bar bar(c.bar_config, md::Potential(c.potential), c.options);
  md::write_lammps_bar(bar, c.potential, c.dt, c.steps, c.bar_every, dir.string());
  if (write_only) {
    fmt::print("{} atoms, {} steps: wrote {} and {}; run `lmp -in {}` there (or under mpirun); the slab stress "
               "(GPa) lands in {}\n",
               bar.system().atoms().size(), c.steps, (dir / md::kLammpsBarData).string(),
               (dir / md::kLammpsBarInput).string(), md::kLammpsBarInput, (dir / md::kLammpsBarStress).string());
    return;
  }
  const md::LammpsRun r = md::run_lammps(dir.string(), ranks);
  if (r.ranks < ranks) fmt::print(stderr, "md: mpirun not on PATH, LAMMPS ran on 1 rank instead of {}\n", ranks);
  const auto samples =
      md::read_lammps_bar_stress((dir / md::kLammpsBarStress).string(), c.dt, c.bar_config.bins);
  const fs::path csv = fs::path(out) / "bar_stress_lammps.csv";
  md::write_bar_stress_csv(csv.string(), samples, bar.slab_centres());
  fmt::print("{} atoms, {} steps through LAMMPS (`{}` in {}) -> {}\n", bar.system().atoms().size(), c.steps,
             r.command, dir.string(), csv.string());
}

}  // namespace

void add_md_commands(CLI::App& app) {
  auto* md = app.add_subcommand("md", "Run an MD-only deck (fcc crystal, EAM/LJ/Sutton-Chen, NVE)");
  struct Args {
    std::string deck, out;
    bool check = false, quiet = false, force = false, lammps = false, lammps_write_only = false;
    int ranks = 1;
  };
  auto args = std::make_shared<Args>();
  md->add_option("deck", args->deck, "MD deck (TOML)")->required();
  md->add_option("--out", args->out, "output directory (default: run-<deck name>)");
  md->add_flag("--check", args->check,
               "validate the deck, the potential file and the memory and work estimates; write nothing");
  md->add_flag("--quiet", args->quiet, "no progress line");
  md->add_flag("--force", args->force, "run even when the work estimate exceeds about a day (never the memory one)");
  auto* lammps = md->add_flag("--lammps", args->lammps,
                              "bar decks: run the bar through LAMMPS (lmp) instead of mpmx's MD; inputs in "
                              "OUT/lammps/, slab stress in OUT/bar_stress_lammps.csv");
  md->add_flag("--lammps-write-only", args->lammps_write_only,
               "bar decks: only write the LAMMPS inputs to OUT/lammps/ (to run on a cluster)")
      ->excludes(lammps);
  md->add_option("--ranks", args->ranks, "MPI ranks for --lammps (mpirun -np N when N > 1)")
      ->check(whole_number(1, 1 << 20))
      ->needs(lammps);
  md->callback([args] {
    auto deck = io::Deck::from_file(args->deck);
    const md::MdConfig config = md::read_md_config(deck);  // parses the potential file too
    const md::Potential potential(config.potential);
    const md::MdBudget budget = md::estimate_md(config, potential.cutoff());
    // Memory always; work unless --force, or when only LAMMPS inputs are written.
    md::check_md_budget(budget, physical_memory_bytes(), args->force || args->lammps_write_only);
    if (args->check) {
      fmt::print("{}: ok ({:.4g} atoms, {} steps, about {} of memory, {:.3g} atom-steps)\n", args->deck,
                 budget.atoms, config.steps, format_bytes(budget.bytes), budget.atom_steps);
      return;
    }
    std::string out = args->out;
    if (out.empty()) out = "run-" + std::filesystem::path(args->deck).stem().string();
    if (std::error_code ec; std::filesystem::exists(out, ec) && !std::filesystem::is_directory(out, ec))
      throw InputError(fmt::format("--out {}: exists and is not a directory", out));
    if (args->lammps || args->lammps_write_only) {
      run_bar_lammps(args->deck, config, out, args->lammps_write_only, args->ranks);
      return;
    }
    const auto r = io::run_staged(
        out, [&](const std::string& dir) { return md::run_md(config, dir, deck.table(), args->quiet); });
    fmt::print("{} atoms, {} steps, {:.3g} s, {:.4g} atom-steps/s, PE {:.6f} eV/atom -> {}/run.json\n", r.atoms,
               r.steps, r.wall_seconds, r.atom_steps_per_second, r.potential_energy_per_atom, out);
  });
}

}  // namespace mpmx::app
