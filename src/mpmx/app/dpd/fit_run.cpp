#include "mpmx/app/dpd/fit_run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/io/run_record.hpp"

namespace mpmx::app::dpd {

namespace {

// The <100> bar speed sqrt(E / rho) of a cubic crystal, E = (C11 - C12)(C11 + 2 C12)/(C11 + C12)
// (GPa, g/cm^3 -> m/s).
double bar_speed_100(double c11, double c12, double rho) {
  const double e = (c11 - c12) * (c11 + 2 * c12) / (c11 + c12);
  return e > 0 ? std::sqrt(e * 1e9 / (rho * 1e3)) : 0.0;
}

// Mass density (g/cm^3) of an fcc crystal of atoms of `mass` (amu), lattice constant a (A):
// amu/A^3 x 1.66054.
double fcc_density(double mass, double a) { return 4 * mass * 1.66053906660 / (a * a * a); }

}  // namespace

FitRunSummary run_fit(const FitConfig& c, const std::string& out_dir, const toml::table& deck_echo, int threads,
                      bool quiet, const FitProgress& from, const std::function<void(const FitProgress&)>& keep) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  const auto t0 = std::chrono::steady_clock::now();
  const md::Potential pot(c.md_potential);
  // Stages: the MD isotherm, the MD strained boxes ([elastic]), then each fit round.
  const int stages = 1 + (c.fit.elastic.on ? 1 : 0) + c.fit.iterations + 1;
  if (c.fit.elastic.on && from.round && !from.md_elastic)
    throw InputError(fmt::format("{}: the checkpoint holds a fit round but not the MD crystal's elastic constants "
                                 "[elastic] asks for; run afresh without --resume",
                                 c.deck_file));
  // A resumed fit starts after its last finished stage.
  int done = from.stages();
  Progress progress("fit-dpd stages", stages, quiet, done);
  FitProgress now = from;
  auto finished = [&] {
    progress.update(++done);
    if (keep) keep(now);
  };
  std::vector<double> lattice;
  for (double r : c.density_ratios) lattice.push_back(c.lattice_constant / std::cbrt(r));
  multiscale::MdIsothermOptions mo = c.md;
  mo.threads = threads;
  if (!now.md) {
    now.md = multiscale::md_isotherm(pot, lattice, mo);
    finished();
  }
  const std::vector<multiscale::IsothermPoint>& md = *now.md;
  multiscale::FitOptions fo = c.fit;
  fo.dpd.threads = threads;
  fo.dpd.mass = fo.atoms_per_particle * pot.mass(0);
  std::vector<double> pm;
  for (const auto& p : md) pm.push_back(p.pressure);
  const double rho0 = multiscale::zero_pressure_density(c.density_ratios, pm);  // MD's, rho / rho0
  multiscale::CubicConstants md_c;
  double md_a0 = 0;  // Angstrom: the MD crystal's zero-pressure lattice constant at the temperature
  if (fo.elastic.on) {
    if (!std::isfinite(rho0))
      throw InputError(fmt::format("{}: [elastic] needs the MD isotherm to cross zero pressure, and it does not "
                                   "between rho/rho0 = {} and {} ([densities] from, to)",
                                   c.deck_file, c.density_ratios.front(), c.density_ratios.back()));
    md_a0 = c.lattice_constant / std::cbrt(rho0);
    if (!now.md_elastic) {
      multiscale::StrainedBoxOptions mo_el = c.md_elastic;
      mo_el.threads = threads;
      now.md_elastic = multiscale::md_strained_constants(pot, md_a0, mo_el);
      finished();
    }
    md_c = *now.md_elastic;
    fo.elastic.c11 = md_c.c11, fo.elastic.c12 = md_c.c12;
    fo.elastic.lattice_constant = std::cbrt(fo.atoms_per_particle) * md_a0;
  }
  fo.resume_from = now.round;
  fo.on_round = [&](const multiscale::FitRound& r) {
    now.round = r;
    finished();
  };
  const multiscale::FitResult fit = multiscale::fit_morse(md, fo);
  progress.finish();

  FitRunSummary s;
  s.potential = fit.potential;
  s.max_deviation_over_range = fit.max_deviation_over_range;
  std::vector<double> pd;
  for (const auto& p : fit.dpd) pd.push_back(p.pressure);
  s.zero_pressure_md = rho0;
  s.zero_pressure_dpd = multiscale::zero_pressure_density(c.density_ratios, pd);

  std::ostringstream csv;
  csv << "density_ratio,density_g_per_cm3,md_lattice_A,coarse_lattice_A,md_pressure_GPa,md_pressure_error_GPa,"
         "md_temperature_K,dpd_pressure_GPa,dpd_pressure_error_GPa,dpd_temperature_K,dpd_static_pressure_GPa,"
         "dpd_thermal_pressure_GPa\n";
  for (std::size_t k = 0; k < md.size(); ++k) {
    const double a = lattice[k];
    const double rho = fcc_density(pot.mass(0), a);
    csv << fmt::format("{:.6f},{:.6f},{:.8f},{:.8f},{:.6f},{:.6f},{:.3f},{:.6f},{:.6f},{:.3f},{:.6f},{:.6f}\n",
                       c.density_ratios[k], rho, a, fit.coarse_lattice[k], md[k].pressure, md[k].pressure_error,
                       md[k].temperature, fit.dpd[k].pressure, fit.dpd[k].pressure_error, fit.dpd[k].temperature,
                       fit.static_pressure[k], fit.thermal[k]);
  }
  io::write_file_atomic((fs::path(out_dir) / "isotherm.csv").string(), csv.str());
  write_potential_file((fs::path(out_dir) / c.potential_file).string(), fit.potential,
                       fmt::format("Fitted by mpmx fit-dpd {} ({}): mesoparticles of {} atoms, {} K isotherm of {}\n"
                                   "max |P_DPDE - P_MD| = {:.3g} of the MD pressure range; zero-pressure rho/rho0 "
                                   "MD {:.5f}, DPDE {:.5f}",
                                   c.deck_file, c.id, fo.atoms_per_particle, c.md.temperature, pot.describe(),
                                   s.max_deviation_over_range, s.zero_pressure_md, s.zero_pressure_dpd));
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  toml::array rho, p_md, p_dpd;
  for (std::size_t k = 0; k < md.size(); ++k) {
    rho.push_back(c.density_ratios[k]);
    p_md.push_back(md[k].pressure);
    p_dpd.push_back(fit.dpd[k].pressure);
  }
  const double rho0_error = std::abs(s.zero_pressure_dpd - s.zero_pressure_md) / s.zero_pressure_md;
  toml::table rec{
      {"version", MPMX_VERSION},
      {"command", "fit-dpd"},
      {"deck_file", c.deck_file},
      {"deck", deck_echo},
      {"case", c.id},
      {"md_potential", pot.describe()},
      {"threads", threads},
      {"wall_seconds", s.wall_seconds},
      {"potential_file", c.potential_file},
      {"potential",
       toml::table{{"style", "morse"}, {"d0", fit.potential.d0}, {"alpha", fit.potential.alpha},
                   {"r0", fit.potential.r0}, {"cutoff", fit.potential.rc}, {"shift", fit.potential.shift}}},
      {"objective_evaluations", fit.evaluations},
      {"isotherm", toml::table{{"density_ratio", rho}, {"md_pressure_GPa", p_md}, {"dpd_pressure_GPa", p_dpd}}},
      {"max_deviation_over_md_range", s.max_deviation_over_range},
      {"zero_pressure_density_ratio", toml::table{{"md", s.zero_pressure_md}, {"dpd", s.zero_pressure_dpd},
                                                  {"relative_difference", rho0_error}}},
      {"targets", toml::table{{"deviation_below_2_percent", s.max_deviation_over_range < 0.02},
                              {"zero_pressure_density_within_half_percent", rho0_error < 0.005}}}};
  if (fo.elastic.on) {
    const multiscale::CubicConstants& dc = fit.dpd_constants;
    const double rho = fcc_density(pot.mass(0), md_a0);
    s.elastic = true;
    s.c11_residual = (dc.c11 - md_c.c11) / md_c.c11;
    s.c12_residual = (dc.c12 - md_c.c12) / md_c.c12;
    toml::table el{
        {"weight", fo.elastic.weight},
        {"strain", md_c.strain},
        {"md", toml::table{{"lattice_constant_A", md_a0},
                           {"pressure_GPa", md_c.pressure},
                           {"c11_GPa", md_c.c11},
                           {"c11_error_GPa", md_c.c11_error},
                           {"c12_GPa", md_c.c12},
                           {"c12_error_GPa", md_c.c12_error},
                           {"bar_speed_100_m_per_s", bar_speed_100(md_c.c11, md_c.c12, rho)}}},
        {"dpd", toml::table{{"coarse_lattice_constant_A", fo.elastic.lattice_constant},
                            {"pressure_GPa", dc.pressure},
                            {"c11_GPa", dc.c11},
                            {"c11_error_GPa", dc.c11_error},
                            {"c12_GPa", dc.c12},
                            {"c12_error_GPa", dc.c12_error},
                            {"born_c11_GPa", fit.born_c11},
                            {"born_c12_GPa", fit.born_c12},
                            {"bar_speed_100_m_per_s", bar_speed_100(dc.c11, dc.c12, rho)}}},
        {"residual", toml::table{{"c11", s.c11_residual}, {"c12", s.c12_residual}}}};
    rec.insert("elastic", std::move(el));
    auto* t = rec["targets"].as_table();
    t->insert("c11_within_5_percent", std::abs(s.c11_residual) < 0.05);
    t->insert("c12_within_5_percent", std::abs(s.c12_residual) < 0.05);
  }
  std::ostringstream os;
  os << toml::json_formatter{rec} << '\n';
  io::write_file_atomic((fs::path(out_dir) / "run.json").string(), os.str());
  return s;
}

}  // namespace mpmx::app::dpd
