#include "mpmx/multiscale/md_to_dpd_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/nelder_mead.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/elastic.hpp"

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

StrainedBoxOptions model_boxes(const FitOptions& o) {
  StrainedBoxOptions b = o.elastic.boxes;
  b.temperature = o.dpd.temperature, b.mass = o.dpd.mass, b.gamma = o.dpd.gamma;
  b.heat_capacity = o.dpd.heat_capacity, b.dt = o.dpd.dt, b.berendsen_tau = o.dpd.berendsen_tau;
  b.threads = o.dpd.threads;
  return b;
}

FitResult fit_morse(const std::vector<IsothermPoint>& md, const FitOptions& o) {
  if (md.size() < 3) throw InputError("fit-dpd: the MD isotherm needs at least 3 densities");
  if (o.elastic.on && !(o.elastic.c11 > 0 && o.elastic.c12 > 0 && o.elastic.lattice_constant > 0))
    throw InputError(fmt::format("fit-dpd: elastic targets C11 = {} and C12 = {} GPa at a = {} Angstrom must be positive",
                                 o.elastic.c11, o.elastic.c12, o.elastic.lattice_constant));
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
  const ElasticTargets& el = o.elastic;
  const StrainedBoxOptions boxes = model_boxes(o);
  double thermal11 = 0, thermal12 = 0;  // first guess: the static constants
  auto born = [&](const dpd::MorsePotential& m) {
    const dpd::LatticeConstants b = dpd::fcc_born_constants(m, el.lattice_constant);
    return std::array<double, 2>{b.c11 * units::eV_per_A3_in_GPa, b.c12 * units::eV_per_A3_in_GPa};
  };
  std::vector<double> th = {std::log(o.start.d0), std::log(o.start.alpha), std::log(o.start.r0)};
  int first = 0;
  if (const auto& from = o.resume_from) {
    if (from->theta.size() != 3 || from->thermal.size() != n || from->next < 1 || from->next > o.iterations)
      throw InputError(fmt::format("fit-dpd: a stopped fit's state does not fit this deck (round {} of {}, {} "
                                   "densities for {})",
                                   from->next, o.iterations, from->thermal.size(), n));
    first = from->next, th = from->theta, thermal = from->thermal;
    thermal11 = from->thermal11, thermal12 = from->thermal12, r.evaluations = from->evaluations;
  }
  for (int it = first; it <= o.iterations; ++it) {
    auto objective = [&](const std::vector<double>& x) {
      const dpd::MorsePotential m = morse_of(x, o.start);
      if (!(m.r0 < m.rc)) return 1e300;
      double s = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const double d = (static_lattice_pressure(m, r.coarse_lattice[k]) + thermal[k] - md[k].pressure) / range;
        s += d * d;
      }
      if (el.on && el.weight > 0) {
        const auto c = born(m);
        const double e11 = (c[0] + thermal11 - el.c11) / el.c11, e12 = (c[1] + thermal12 - el.c12) / el.c12;
        s += el.weight * static_cast<double>(n) * 0.5 * (e11 * e11 + e12 * e12);
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
    if (el.on) {
      const auto c = born(r.potential);
      r.born_c11 = c[0], r.born_c12 = c[1];
      r.dpd_constants = dpd_strained_constants(r.potential, el.lattice_constant, boxes);
      thermal11 = r.dpd_constants.c11 - c[0];
      thermal12 = r.dpd_constants.c12 - c[1];
    }
    if (it == o.iterations) break;
    if (o.on_round) o.on_round(FitRound{it + 1, th, thermal, thermal11, thermal12, r.evaluations});
  }
  r.thermal = thermal;
  r.max_deviation_over_range = 0;
  for (std::size_t k = 0; k < n; ++k)
    r.max_deviation_over_range = std::max(r.max_deviation_over_range, std::abs(r.dpd[k].pressure - md[k].pressure) / range);
  return r;
}

}  // namespace mpmx::multiscale
