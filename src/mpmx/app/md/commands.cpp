// `mpmx md DECK --out DIR [--check] [--force] [--lammps [--ranks N] | --lammps-write-only]`:
// an MD-only run (issue 3); for a bar deck, optionally its reference through LAMMPS.
// `--check` does every validation the run does (deck, potential file and its elements,
// memory and work estimates) and writes nothing; the run creates DIR only after them.
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "mpmx/io/run_manifest.hpp"
#include "mpmx/app/cli_checks.hpp"
#include "mpmx/app/deck_kind.hpp"
#include "mpmx/app/commands.hpp"
#include "mpmx/app/md/budget.hpp"
#include "mpmx/app/md/config.hpp"
#include "mpmx/app/md/deck_warnings.hpp"
#include "mpmx/app/md/jet_run.hpp"
#include "mpmx/app/md/lammps_bar.hpp"
#include "mpmx/app/md/lammps_jet.hpp"
#include "mpmx/app/md/run.hpp"
#include "mpmx/app/run_folder.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/io/plot.hpp"
#include "mpmx/io/staged_dir.hpp"
#include "mpmx/md/bar.hpp"

namespace mpmx::app {

namespace {

// The bar of a deck through LAMMPS instead of mpmx's own MD: inputs in OUT/lammps/,
// then (unless write_only) lmp, and its slab stress as OUT/bar_stress_lammps.csv. Written
// into `stage` (the staging folder of OUT, io/staged_dir.hpp); messages name OUT.
void run_bar_lammps(const std::string& deck, const md::MdConfig& c, const std::string& out, const std::string& stage,
                    bool write_only, int ranks) {
  namespace fs = std::filesystem;
  if (!c.bar)
    throw InputError(fmt::format("{}: --lammps and --lammps-write-only need a deck with a [bar] or [jet] table", deck));
  const fs::path dir = fs::path(stage) / "lammps", shown = fs::path(out) / "lammps";
  const md::Bar bar(c.bar_config, md::Potential(c.potential), c.options);
  md::write_lammps_bar(bar, c.potential, c.dt, c.steps, c.bar_every, dir.string());
  if (write_only) {
    fmt::print("{} atoms, {} steps: wrote {} and {}; run `lmp -in {}` there (or under mpirun); the slab stress "
               "(GPa) lands in {}\n",
               bar.system().atoms().size(), c.steps, (shown / md::kLammpsBarData).string(),
               (shown / md::kLammpsBarInput).string(), md::kLammpsBarInput, (shown / md::kLammpsBarStress).string());
    return;
  }
  const md::LammpsRun r = md::run_lammps(dir.string(), ranks);
  if (r.ranks < ranks) fmt::print(stderr, "md: mpirun not on PATH, LAMMPS ran on 1 rank instead of {}\n", ranks);
  const auto samples =
      md::read_lammps_bar_stress((dir / md::kLammpsBarStress).string(), c.dt, c.bar_config.bins);
  const fs::path csv = fs::path(stage) / "bar_stress_lammps.csv";
  md::write_bar_stress_csv(csv.string(), samples, bar.slab_centres());
  fmt::print("{} atoms, {} steps through LAMMPS (`{}` in {}) -> {}\n", bar.system().atoms().size(), c.steps,
             r.command, shown.string(), (fs::path(out) / "bar_stress_lammps.csv").string());
}

// The jet of a deck through LAMMPS: inputs in OUT/lammps/, then (unless write_only) lmp,
// and its bins' stress as OUT/jet_stress_lammps.csv (long table, one row per bin and record).
void run_jet_lammps(const md::MdConfig& c, const std::string& out, const std::string& stage, bool write_only,
                    int ranks) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(stage) / "lammps", shown = fs::path(out) / "lammps";
  md::JetGeometry geo;
  const md::System sys = md::build_jet(c.jet_config, md::Potential(c.potential), c.options, &geo);
  const md::BinGrid grid = md::jet_grid(geo, c.jet_bins[0], c.jet_bins[1]);
  md::write_lammps_jet(sys, geo, grid, c.potential, c.dt, c.steps, c.jet_every, c.dump_every, dir.string());
  if (write_only) {
    fmt::print("{} atoms, {} steps: wrote {} and {}; run `lmp -in {}` there (or under mpirun); the bins' stress "
               "(GPa) lands in {}\n",
               sys.atoms().size(), c.steps, (shown / md::kLammpsJetData).string(),
               (shown / md::kLammpsJetInput).string(), md::kLammpsJetInput, (shown / md::kLammpsJetStress).string());
    return;
  }
  const md::LammpsRun r = md::run_lammps(dir.string(), ranks, md::kLammpsJetInput, md::kLammpsJetStress);
  if (r.ranks < ranks) fmt::print(stderr, "md: mpirun not on PATH, LAMMPS ran on 1 rank instead of {}\n", ranks);
  const auto samples = md::read_lammps_bar_stress((dir / md::kLammpsJetStress).string(), c.dt, grid.nx * grid.ny);
  const fs::path csv = fs::path(stage) / "jet_stress_lammps.csv";
  std::ofstream f(csv);
  if (!f) throw SystemError(fmt::format("cannot write {}: {}", csv.string(), std::strerror(errno)));
  f << "step,time_ps,ix,iy,x_A,y_A,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,sxz_GPa,syz_GPa\n";
  for (const auto& s : samples)
    for (int k = 0; k < grid.nx * grid.ny; ++k) {
      const md::Mat3& m = s.stress_gpa[k];
      const int ix = k % grid.nx, iy = k / grid.nx;
      f << fmt::format("{},{:.6f},{},{},{:.6g},{:.6g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", s.step, s.time_ps,
                       ix, iy, grid.x_centre(ix), grid.y_centre(iy), m[0], m[4], m[8], m[1], m[2], m[5]);
    }
  if (!f) throw SystemError(fmt::format("error writing {}: {}", csv.string(), std::strerror(errno)));
  fmt::print("{} atoms, {} steps through LAMMPS (`{}` in {}) -> {}\n", sys.atoms().size(), c.steps, r.command,
             shown.string(), (fs::path(out) / "jet_stress_lammps.csv").string());
}

// The oriented crystal's periodic tile and box: what `check` states of [lattice].
// `what`: "box", "bar", the jet or the rod; `cells`: its tiles along x, y, z.
void print_lattice(const md::MdConfig& c, const std::string& what, const std::array<int, 3>& cells, double strain_x) {
  const particles::LatticeSpec& l = c.lattice;
  const particles::LatticeTile tile = particles::lattice_tile(l);
  const auto& o = l.orient;
  std::string shape = l.style == particles::LatticeStyle::hcp ? fmt::format(", c/a {:.6g}", l.c_over_a) : "";
  fmt::print("  lattice: {} a = {:.6g} A{}, x [{},{},{}] y [{},{},{}] z [{},{},{}]: periodic tile {:.6g} x {:.6g} x "
             "{:.6g} A of {} atoms; {} {} x {} x {} tiles = {:.6g} x {:.6g} x {:.6g} A, {} atoms\n",
             particles::lattice_name(l.style), l.constant, shape, o[0][0], o[0][1], o[0][2], o[1][0], o[1][1], o[1][2],
             o[2][0], o[2][1], o[2][2], tile.length[0], tile.length[1], tile.length[2], tile.atoms, what, cells[0],
             cells[1], cells[2], cells[0] * tile.length[0] * (1 + strain_x), cells[1] * tile.length[1],
             cells[2] * tile.length[2], tile.atoms * cells[0] * cells[1] * cells[2]);
}

// `md --check`, and `mpmx check` of an md deck: every validation the run makes (deck,
// potential file and its elements, memory always, work over a day unless `force`) and
// the estimate at the rate of a 500-atom box of the deck's potential timed on this core.
void check_md(const std::string& path, bool force, bool lammps = false) {
  auto deck = io::Deck::from_file(path);
  md::MdConfig config = md::read_md_config(deck);
  if (lammps && !config.jet && !config.bar)  // as the run refuses it
    throw InputError(fmt::format("{}: --lammps and --lammps-write-only need a deck with a [bar] or [jet] table", path));
  config.options.threaded = true;
  const md::Potential potential(config.potential);
  const md::MdBudget budget = md::estimate_md(config, potential.cutoff());
  md::check_md_budget(budget, physical_memory_bytes(), force);
  md::SystemOptions one = config.options;
  one.threaded = false;
  // Timed on an fcc box of the crystal's atom density (as many neighbours a pair list holds).
  double timed_a = config.lattice_constant;
  if (!config.lattice.plain_fcc()) {
    const particles::LatticeTile tile = particles::lattice_tile(config.lattice);
    timed_a = std::cbrt(4.0 * tile.length[0] * tile.length[1] * tile.length[2] / static_cast<double>(tile.atoms));
  }
  double rate = md::measure_atom_steps_per_second(potential, one, timed_a, 5, config.temperature, 1, config.dt);
  const bool measured = rate > 0;
  if (!measured) rate = md::kMdAtomStepsPerSecond;
  fmt::print("{}: ok (md deck: {:.4g} atoms, {} steps, about {} of memory, {:.3g} atom-steps, about {:.3g} h on one "
             "core at {:.3g} atom-steps/s ({}))\n",
             path, budget.atoms, config.steps + (config.rod ? config.rod_equilibrate_steps : 0),  // checked at read
             format_bytes(budget.bytes), budget.atom_steps,
             budget.atom_steps / rate / 3600.0, rate,
             measured ? "a box of its potential timed on this core just now" : "a typical figure");
  if (!config.bar && !config.jet && !config.rod) print_lattice(config, "box", config.cells, config.strain_x);
  // A sample's counts are tiles of the oriented lattice: say how long they are.
  if (!config.lattice.plain_fcc()) {
    const md::JetConfig& j = config.jet_config;
    const md::RodConfig& r = config.rod_config;
    if (config.bar)
      print_lattice(config, "bar", {config.bar_config.cells_x, config.bar_config.cells_yz, config.bar_config.cells_yz},
                    0.0);
    if (config.jet)
      print_lattice(config, fmt::format("jet (scale {:.6g}, piston {} tiles; before the notch)", j.scale, j.npiston()),
                    {j.nx(), j.ny(), j.nz()}, 0.0);
    if (config.rod)
      print_lattice(config, fmt::format("rod (flyer {} + target {} tiles along x)", r.flyer_cells, r.target_cells[0]),
                    {r.flyer_cells + r.target_cells[0], r.target_cells[1], r.target_cells[2]}, 0.0);
  }
  if (config.ensemble != "nve") {
    const md::NoseHooverOptions& nh = config.nose_hoover;
    std::string what = nh.hugoniot ? fmt::format("the Hugoniostat: {:.6g} GPa along its shock axis, the thermostat's "
                                                 "target from the Hugoniot about the box the run starts with",
                                                 nh.pressure[0])
                                   : "";
    if (!nh.hugoniot && nh.thermostat) what = fmt::format("Nose-Hoover chain at {:.6g} K (t_damp {:.3g} ps)", nh.temperature, nh.t_damp);
    if (!nh.hugoniot && nh.barostat)
      what += fmt::format("{}MTK barostat, {} at {} GPa (p_damp {:.3g} ps)", what.empty() ? "" : ", ",
                          nh.isotropic ? "isotropic" : "per axis",
                          nh.isotropic ? fmt::format("{:.6g}", nh.pressure[0])
                                       : fmt::format("[{:.6g}, {:.6g}, {:.6g}]", nh.pressure[0], nh.pressure[1], nh.pressure[2]),
                          nh.p_damp);
    fmt::print("  ensemble {}: {}\n", config.ensemble, what);
  }
  if (budget.bins > 0)
    fmt::print("  {:.4g} bins: about {} of bin tables and images over the run\n", budget.bins,
               format_bytes(budget.output_bytes));
  if (config.elastic)
    fmt::print("  elastic: the 0 K tensor of this crystal at {}, strained by +-{:g} in each Voigt component{}, "
               "after the run (run.json's elastic)\n",
               config.elastic_at_minimum ? "the potential's minimum" : "[lattice].constant", config.elastic_strain,
               config.lattice.style == particles::LatticeStyle::hcp && config.elastic_relax
                   ? ", the atoms relaxed in each strained box"
                   : "");
  for (const std::string& w : md::md_deck_warnings(config, potential)) fmt::print("  warning: {}\n", w);
}

}  // namespace

void add_md_commands(CLI::App& app) {
  register_deck_check(DeckKind::md, [](const std::string& path, bool force) { check_md(path, force); });
  auto* md = app.add_subcommand("md", "Run an MD-only deck (fcc, bcc or hcp crystal in any orientation, EAM/LJ/Sutton-Chen, NVE)");
  struct Args {
    std::string deck, out;
    bool check = false, quiet = false, force = false, lammps = false, lammps_write_only = false, resume = false,
         still = false, overwrite = false, no_plot = false;
    int ranks = 1, threads = 0;  // all cores, as run and dpd
    std::int64_t stop_after = 0;
  };
  auto args = std::make_shared<Args>();
  md->add_option("deck", args->deck, "MD deck (TOML)")->required();
  md->add_option("--threads,-j", args->threads,
                 "OpenMP threads over the atoms (default: all cores, as run and dpd; results are the same for any count)");
  md->add_option("--out,-o", args->out, "output directory (default runs/<deck name>, as run)");
  md->add_flag("--check", args->check,
               "validate the deck, the potential file and the memory and work estimates; write nothing");
  md->add_flag("--quiet,-q", args->quiet, "no progress line");
  md->add_flag("--no-plot", args->no_plot,
               "no figure of a deck's [scan] (energy_vs_lattice.png); other md decks draw none");
  md->add_flag("--force", args->force, "run even when the work estimate exceeds about a day (never the memory one)");
  md->add_flag("--resume", args->resume,
               "continue from OUT/checkpoint.bin, written by Ctrl-C or SIGTERM at a record (bit-for-bit; refused when "
               "the deck or a file it reads changed since)");
  md->add_flag("--overwrite", args->overwrite, kOverwriteHelp);
  md->add_flag("--still", args->still,
               "rod decks: the flyer released at rest, the undriven twin of the run, which "
               "tools/plot/dpd_study.py subtracts to leave the wave alone");
  // For tests: stop as if interrupted at the first record at or past step N.
  md->add_option("--stop-after", args->stop_after, "")->group("")->check(CLI::NonNegativeNumber);
  auto* lammps = md->add_flag("--lammps", args->lammps,
                              "bar and jet decks: run the sample through LAMMPS (lmp) instead of mpmx's MD; "
                              "inputs in OUT/lammps/, binned stress in OUT/bar_stress_lammps.csv or "
                              "OUT/jet_stress_lammps.csv");
  md->add_flag("--lammps-write-only", args->lammps_write_only,
               "bar and jet decks: only write the LAMMPS inputs to OUT/lammps/ (to run on a cluster)")
      ->excludes(lammps);
  md->add_option("--ranks", args->ranks, "MPI ranks for --lammps (mpirun -np N when N > 1)")
      ->check(whole_number(1, 1 << 20))
      ->needs(lammps);
  md->callback([args, md] {
    require_deck_kind(args->deck, DeckKind::md);
    if (args->check) {
      say_ignored_by_check(*md);
      return check_md(args->deck, args->force || args->lammps_write_only, args->lammps || args->lammps_write_only);
    }
    auto deck = io::Deck::from_file(args->deck);
    md::MdConfig config = md::read_md_config(deck);  // parses the potential file too
    if (config.scan_points == 0) say_ignored(*md, {{"--no-plot", "md draws figures only of a [scan]"}});
    if (args->still && !config.rod) throw InputError(fmt::format("{}: --still needs a deck with a [rod] table", args->deck));
    config.still = args->still;
    // mpmx md advances one large system: its threaded form (the same bits for any count).
    config.options.threaded = true;
    const md::Potential potential(config.potential);
    const md::MdBudget budget = md::estimate_md(config, potential.cutoff());
    for (const std::string& w : md::md_deck_warnings(config, potential)) fmt::print(stderr, "md: warning: {}\n", w);
    config.options.threads = threads_for(threads_of(args->threads), budget.atoms, kAtomsPerMdThread);
    // Memory always; work unless --force, or when only LAMMPS inputs are written.
    md::check_md_budget(budget, physical_memory_bytes(), args->force || args->lammps_write_only);
    const std::string out = out_dir_of(args->out, args->deck);
    const io::FolderOwner owner{io::run_owner("md", args->deck), args->overwrite};
    if (args->lammps || args->lammps_write_only) {
      if (!config.jet && !config.bar)
        throw InputError(
            fmt::format("{}: --lammps and --lammps-write-only need a deck with a [bar] or [jet] table", args->deck));
      if (args->resume) throw InputError("--resume continues mpmx's own MD, not a --lammps run");
      io::run_staged(
          out,
          [&](const std::string& dir) {
            if (config.jet) run_jet_lammps(config, out, dir, args->lammps_write_only, args->ranks);
            else run_bar_lammps(args->deck, config, out, dir, args->lammps_write_only, args->ranks);
            return 0;
          },
          owner);
      return;
    }
    RunControlOptions o;
    o.quiet = args->quiet;
    o.resume = args->resume;
    o.stop_after = args->stop_after;
    o.out = out;
    const auto r = run_resumable(out, args->resume, owner,
                                 [&](const std::string& dir) { return md::run_md(config, dir, deck.table(), o); });
    if (r.interrupted)
      throw Interrupted(fmt::format("step {} of {} written to {}; continue with: mpmx md {} --out {} --resume{}",
                                    r.step, r.last_step, checkpoint_path(out), args->deck, out,
                                    args->still ? " --still" : ""));
    // After --resume the time and rate are this invocation's: say its steps too.
    const std::string now =
        r.steps_now == r.steps ? std::string() : fmt::format(" ({} of them now, after --resume)", r.steps_now);
    fmt::print("{} atoms, {} steps{}, {:.3g} s, {:.4g} atom-steps/s, PE {:.6f} eV/atom -> {}/run.json\n", r.atoms,
               r.steps, now, r.wall_seconds, r.atom_steps_per_second, r.potential_energy_per_atom, out);
    for (const std::string& line : r.notes) fmt::print("  {}\n", line);
    // The scan's curve (M1, fig. 7.2), as a continuum run draws its figures.
    if (config.scan_points > 0 && !args->no_plot && io::matplotlib_present())
      io::run_plot_script("md_scan.py", fmt::format("'{}' >/dev/null", out));
  });
}

}  // namespace mpmx::app
