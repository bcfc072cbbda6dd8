#include "mpmx/multiscale/md_to_dpd_fit.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/nelder_mead.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::multiscale {

namespace {

// Parameters as logs (all positive): theta = (ln D0, ln alpha, ln r0).
dpd::MorsePotential morse_of(const std::vector<double>& th, const dpd::MorsePotential& base) {
  dpd::MorsePotential m = base;
  m.d0 = std::exp(th[0]);
  m.alpha = std::exp(th[1]);
  m.r0 = std::exp(th[2]);
  m.update_offset();
  return m;
}

}  // namespace

FitResult fit_morse(const std::vector<IsothermPoint>& md, const FitOptions& o) {
  if (md.size() < 3) throw InputError("fit-dpd: the MD isotherm needs at least 3 densities");
  FitResult r;
  r.md = md;
  const double scale = std::cbrt(o.atoms_per_particle);
  for (const auto& p : md) {
    r.md_lattice.push_back(p.lattice_constant);
    r.coarse_lattice.push_back(scale * p.lattice_constant);
  }
  const std::size_t n = md.size();
  double pmin = md[0].pressure, pmax = md[0].pressure;
  for (const auto& p : md) pmin = std::min(pmin, p.pressure), pmax = std::max(pmax, p.pressure);
  const double range = std::max(pmax - pmin, 1e-12);

  // First thermal guess: the mesoparticles' ideal-gas pressure k_B T / Omega.
  std::vector<double> thermal(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = r.coarse_lattice[k];
    thermal[k] = units::boltzmann_eV_per_K * o.dpd.temperature / (a * a * a / 4.0) * units::eV_per_A3_in_GPa;
  }
  std::vector<double> th = {std::log(o.start.d0), std::log(o.start.alpha), std::log(o.start.r0)};
  for (int it = 0; it <= o.iterations; ++it) {
    auto objective = [&](const std::vector<double>& x) {
      const dpd::MorsePotential m = morse_of(x, o.start);
      if (!(m.r0 < m.rc)) return 1e300;
      double s = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const double d = (static_lattice_pressure(m, r.coarse_lattice[k]) + thermal[k] - md[k].pressure) / range;
        s += d * d;
      }
      return s;
    };
    // Restarted simplex (a Nelder-Mead convention against premature collapse).
    for (int restart = 0; restart < 3; ++restart) {
      const NelderMeadResult nm = nelder_mead(objective, th, {0.1, 0.05, 0.02}, 3000, 1e-16);
      th = nm.x;
      r.evaluations += nm.evaluations;
    }
    r.potential = morse_of(th, o.start);
    r.dpd = dpd_isotherm(r.potential, r.coarse_lattice, o.dpd);
    r.static_pressure.assign(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      r.static_pressure[k] = static_lattice_pressure(r.potential, r.coarse_lattice[k]);
      thermal[k] = r.dpd[k].pressure - r.static_pressure[k];
    }
    if (it == o.iterations) break;
  }
  r.thermal = thermal;
  r.max_deviation_over_range = 0;
  for (std::size_t k = 0; k < n; ++k)
    r.max_deviation_over_range = std::max(r.max_deviation_over_range, std::abs(r.dpd[k].pressure - md[k].pressure) / range);
  return r;
}

}  // namespace mpmx::multiscale
