#include "mpmx/app/dpd/fit_config.hpp"

#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "mpmx/app/case_table.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/md/physical_bounds.hpp"
#include "mpmx/md/potential/registry.hpp"

namespace mpmx::app::dpd {

FitConfig read_fit_config(io::Deck& deck) {
  FitConfig c;
  c.deck_file = deck.name();
  const std::string deck_dir = std::filesystem::path(deck.name()).parent_path().string();
  auto root = deck.root();
  const CaseTable cs = read_case_table(root, deck.name(), true, "metal");
  c.id = cs.id;  // printed on progress and result lines
  c.title = cs.title;
  c.seed_ref = cs.seed;

  auto md = root.table("md");
  io::Section pot = md.table("potential");
  c.md_potential = md::read_potential(pot, deck_dir);
  c.lattice_constant = md.number("lattice_constant");
  md.check(c.lattice_constant >= 0.5 && c.lattice_constant <= 100, "lattice_constant",
           "must lie in [0.5, 100] Angstrom (an atomic crystal's)");
  if (const std::string why = md::fcc_constant_problem(c.lattice_constant); !why.empty())
    md.check(false, "lattice_constant", why);
  c.md.cells = md.integer_int("cells", 5, 2, 40);  // fcc cells per edge
  c.md.temperature = md.number("temperature");
  md.positive("temperature", c.md.temperature);
  md.temperature("temperature", c.md.temperature);
  c.md.dt = md.number("dt", 0.002);
  md.check(c.md.dt > 0 && c.md.dt <= 0.01, "dt", "must lie in (0, 0.01] ps");
  c.md.equilibrate_steps = md.integer_int("equilibrate_steps", 3000, 0, 100000000);
  c.md.sample_steps = md.integer_int("sample_steps", 3000, 100, 100000000);
  const auto seed = md.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max());
  c.md.seed = static_cast<std::uint64_t>(seed);

  auto dn = root.table("densities");
  const double from = dn.number("from", 0.9), to = dn.number("to", 1.1);
  const int points = dn.integer_int("points", 11, 3, 101);
  dn.check(from > 0.5 && from < 1.0, "from", "must lie in (0.5, 1): rho / rho0 of the least dense sample");
  dn.check(to > 1.0 && to < 1.5, "to", "must lie in (1, 1.5): rho / rho0 of the densest sample");
  for (int k = 0; k < points && points >= 3 && points <= 101; ++k)
    c.density_ratios.push_back(from + (to - from) * k / (points - 1));

  auto dp = root.table("dpd");
  multiscale::FitOptions& f = c.fit;
  f.atoms_per_particle = dp.number("atoms_per_particle", 8.0);
  dp.check(f.atoms_per_particle >= 1 && f.atoms_per_particle <= 1e6, "atoms_per_particle",
           "must be from 1 to 1e6");
  f.start.rc = dp.number("cutoff");
  dp.positive("cutoff", f.start.rc);
  f.start.shift = dp.boolean("shift", true);
  auto st = dp.table("start");
  f.start.d0 = st.number("d0");
  st.positive("d0", f.start.d0);
  f.start.alpha = st.number("alpha");
  st.positive("alpha", f.start.alpha);
  f.start.r0 = st.number("r0");
  st.check(f.start.r0 > 0 && f.start.r0 < f.start.rc, "r0", "must lie between 0 and dpd.cutoff");
  f.start.update_offset();
  f.iterations = dp.integer_int("iterations", 3, 0, 20);
  multiscale::DpdIsothermOptions& d = f.dpd;
  d.cells = dp.integer_int("cells", 4, 2, 40);  // coarse fcc cells per edge
  d.temperature = c.md.temperature;
  d.gamma = dp.number("gamma", 0.2);
  dp.positive("gamma", d.gamma);
  const double cv = dp.number("heat_capacity_kB", 3.0 * f.atoms_per_particle - 3.0);
  dp.positive("heat_capacity_kB", cv);
  d.heat_capacity = cv * units::boltzmann_eV_per_K;
  d.dt = dp.number("dt", 0.005);
  dp.check(d.dt > 0 && d.dt <= 0.1, "dt", "must lie in (0, 0.1] ps");
  d.skin = dp.number("skin", 1.0);
  dp.check(d.skin >= 0 && d.skin <= f.start.rc, "skin", "must lie in [0, dpd.cutoff] Angstrom");
  d.berendsen_tau = dp.number("berendsen_tau", 0.5);
  dp.check(d.berendsen_tau >= d.dt, "berendsen_tau", "must be at least dpd.dt");
  d.equilibrate_steps = dp.integer_int("equilibrate_steps", 1000, 0, 100000000);
  d.sample_steps = dp.integer_int("sample_steps", 2000, 100, 100000000);
  const auto dseed = dp.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max());
  d.seed = static_cast<std::uint64_t>(dseed);

  // Optional elastic targets: the MD crystal's C11 and C12 at the temperature.
  auto el = root.optional_table("elastic");
  f.elastic.on = el.present();
  if (f.elastic.on) {
    f.elastic.weight = el.number("weight", 1.0);
    el.check(f.elastic.weight >= 0 && f.elastic.weight <= 1e6, "weight",
             "must lie in [0, 1e6] (0: the constants are measured and reported, not fitted)");
    const double strain = el.number("strain", 0.01);
    el.check(strain >= 1e-4 && strain <= 0.05, "strain", "must lie in [1e-4, 0.05]: the boxes' +- strain along x");
    multiscale::StrainedBoxOptions& m = c.md_elastic;
    m.strain = strain, m.temperature = c.md.temperature, m.dt = c.md.dt, m.seed = c.md.seed + 7;
    m.cells = el.integer_int("md_cells", c.md.cells, 2, 40);
    m.equilibrate_steps = el.integer_int("md_equilibrate_steps", c.md.equilibrate_steps, 0, 100000000);
    m.sample_steps = el.integer_int("md_sample_steps", 5000, 100, 100000000);
    multiscale::StrainedBoxOptions& b = f.elastic.boxes;
    b.strain = strain, b.seed = d.seed + 7;
    b.cells = el.integer_int("dpd_cells", d.cells, 2, 40);
    b.equilibrate_steps = el.integer_int("dpd_equilibrate_steps", d.equilibrate_steps, 0, 100000000);
    b.sample_steps = el.integer_int("dpd_sample_steps", 4000, 100, 100000000);
  }

  auto out = root.optional_table("output");
  c.potential_file = out.string("potential_file", "dpd_potential.toml");
  out.check(!c.potential_file.empty() && c.potential_file.find('/') == std::string::npos, "potential_file",
            "must be a plain file name (written into the output folder)");
  // Not a name the run writes itself, nor a folder name: it would overwrite run.json,
  // isotherm.csv or a stopped fit's checkpoint, or fail only after the whole fit (".staging" would lose the output).
  out.check(c.potential_file != "run.json" && c.potential_file != "isotherm.csv" &&
                c.potential_file != "checkpoint.bin",
            "potential_file", "is one of the fit's own outputs (run.json, isotherm.csv, checkpoint.bin): choose another name");
  out.check(c.potential_file.front() != '.', "potential_file",
            "must not start with '.' (\".\", \"..\" and the staging folder \".staging\" are folders)");
  deck.finish();
  return c;
}

void write_potential_file(const std::string& path, const MorsePotential& m, const std::string& comment) {
  std::string c = "# ";
  for (char ch : comment) c += ch == '\n' ? std::string("\n# ") : std::string(1, ch);
  io::write_file_atomic(path, fmt::format("{}\n[potential]\nstyle = \"morse\"\nd0 = {:.17g}\nalpha = {:.17g}\n"
                                          "r0 = {:.17g}\ncutoff = {:.17g}\nshift = {}\n",
                                          c, m.d0, m.alpha, m.r0, m.rc, m.shift ? "true" : "false"));
}

}  // namespace mpmx::app::dpd
