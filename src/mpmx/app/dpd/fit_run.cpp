#include "mpmx/app/dpd/fit_run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/io/run_record.hpp"

namespace mpmx::app::dpd {

FitRunSummary run_fit(const FitConfig& c, const std::string& out_dir, const toml::table& deck_echo, int threads) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  const auto t0 = std::chrono::steady_clock::now();
  const md::Potential pot(c.md_potential);
  std::vector<double> lattice;
  for (double r : c.density_ratios) lattice.push_back(c.lattice_constant / std::cbrt(r));
  multiscale::MdIsothermOptions mo = c.md;
  mo.threads = threads;
  const std::vector<multiscale::IsothermPoint> md = multiscale::md_isotherm(pot, lattice, mo);
  multiscale::FitOptions fo = c.fit;
  fo.dpd.threads = threads;
  fo.dpd.mass = fo.atoms_per_particle * pot.mass(0);
  const multiscale::FitResult fit = multiscale::fit_morse(md, fo);

  FitRunSummary s;
  s.potential = fit.potential;
  s.max_deviation_over_range = fit.max_deviation_over_range;
  std::vector<double> pm, pd;
  for (std::size_t k = 0; k < md.size(); ++k) pm.push_back(md[k].pressure), pd.push_back(fit.dpd[k].pressure);
  s.zero_pressure_md = multiscale::zero_pressure_density(c.density_ratios, pm);
  s.zero_pressure_dpd = multiscale::zero_pressure_density(c.density_ratios, pd);

  std::ostringstream csv;
  csv << "density_ratio,density_g_per_cm3,md_lattice_A,coarse_lattice_A,md_pressure_GPa,md_pressure_error_GPa,"
         "md_temperature_K,dpd_pressure_GPa,dpd_pressure_error_GPa,dpd_temperature_K,dpd_static_pressure_GPa,"
         "dpd_thermal_pressure_GPa\n";
  for (std::size_t k = 0; k < md.size(); ++k) {
    const double a = lattice[k];
    const double rho = 4 * pot.mass(0) * 1.66053906660 / (a * a * a);  // g/cm^3 (amu/A^3 x 1.66054)
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
  std::ostringstream os;
  os << toml::json_formatter{rec} << '\n';
  io::write_file_atomic((fs::path(out_dir) / "run.json").string(), os.str());
  return s;
}

}  // namespace mpmx::app::dpd
