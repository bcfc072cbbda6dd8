// `mpmx md DECK --out DIR [--check]`: an MD-only run (issue 3).
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/app/commands.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/md/config.hpp"
#include "mpmx/md/run.hpp"

namespace mpmx::app {

void add_md_commands(CLI::App& app) {
  auto* md = app.add_subcommand("md", "Run an MD-only deck (fcc crystal, EAM/LJ/Sutton-Chen, NVE)");
  struct Args {
    std::string deck, out;
    bool check = false, quiet = false;
  };
  auto args = std::make_shared<Args>();
  md->add_option("deck", args->deck, "MD deck (TOML)")->required();
  md->add_option("--out", args->out, "output directory (default: run-<deck name>)");
  md->add_flag("--check", args->check, "validate the deck and exit");
  md->add_flag("--quiet", args->quiet, "no progress line");
  md->callback([args] {
    auto deck = io::Deck::from_file(args->deck);
    const md::MdConfig config = md::read_md_config(deck);
    if (args->check) {
      fmt::print("{}: ok\n", args->deck);
      return;
    }
    std::string out = args->out;
    if (out.empty()) out = "run-" + std::filesystem::path(args->deck).stem().string();
    const auto r = md::run_md(config, out, deck.table(), args->quiet);
    fmt::print("{} atoms, {} steps, {:.3g} s, {:.4g} atom-steps/s, PE {:.6f} eV/atom -> {}/run.json\n", r.atoms,
               r.steps, r.wall_seconds, r.atom_steps_per_second, r.potential_energy_per_atom, out);
  });
}

}  // namespace mpmx::app
