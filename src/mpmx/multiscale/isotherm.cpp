#include "mpmx/multiscale/isotherm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/setup.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"

namespace mpmx::multiscale {

double mean_pressure(const particles::Mat3& s) { return -(s[0] + s[4] + s[8]) / 3.0; }

void block_average(const std::vector<double>& s, double& mean, double& error) {
  const int blocks = 10;
  const std::size_t per = std::max<std::size_t>(1, s.size() / blocks);
  std::vector<double> b;
  for (std::size_t k = 0; k + per <= s.size() && b.size() < static_cast<std::size_t>(blocks); k += per)
    b.push_back(std::accumulate(s.begin() + k, s.begin() + k + per, 0.0) / per);
  mean = std::accumulate(b.begin(), b.end(), 0.0) / b.size();
  double v = 0;
  for (double x : b) v += (x - mean) * (x - mean);
  error = b.size() > 1 ? std::sqrt(v / (b.size() - 1) / b.size()) : 0.0;
}

void rescale_temperature(md::System& s, double temperature) {
  const double t = s.temperature();
  if (!(t > 0)) return;
  particles::Atoms& at = s.edit_atoms();
  double px = 0, py = 0, pz = 0;
  for (std::size_t i = 0; i < at.size(); ++i) px += at.vx[i], py += at.vy[i], pz += at.vz[i];
  const double m = static_cast<double>(at.size());
  const double f = std::sqrt(temperature / t);
  for (std::size_t i = 0; i < at.size(); ++i) {
    at.vx[i] = px / m + f * (at.vx[i] - px / m);
    at.vy[i] = py / m + f * (at.vy[i] - py / m);
    at.vz[i] = pz / m + f * (at.vz[i] - pz / m);
  }
}

void advance_at_temperature(md::System& s, int steps, double dt, double temperature) {
  for (int done = 0; done < steps; done += 50) {
    s.advance(std::min(50, steps - done), dt);
    rescale_temperature(s, temperature);
  }
}

std::vector<IsothermPoint> md_isotherm(const md::Potential& pot, const std::vector<double>& lattice_constants,
                                       const MdIsothermOptions& o) {
  const int n = static_cast<int>(lattice_constants.size());
  std::vector<IsothermPoint> out(n);
#pragma omp parallel for schedule(dynamic, 1) num_threads(o.threads)
  for (int k = 0; k < n; ++k) {
    const double a = lattice_constants[k];
    md::System s(particles::fcc(o.cells, o.cells, o.cells, a), pot);
    s.thermalize(o.temperature, o.seed, static_cast<std::uint64_t>(k));
    // Velocities rescaled to the isotherm's temperature every 50 steps, throughout.
    advance_at_temperature(s, o.equilibrate_steps, o.dt, o.temperature);
    std::vector<double> p, t;
    for (int done = 0; done < o.sample_steps; done += 10) {
      s.advance(10, o.dt);
      p.push_back(mean_pressure(s.stress_gpa()));
      t.push_back(s.temperature());
      if ((done + 10) % 50 == 0) rescale_temperature(s, o.temperature);
    }
    IsothermPoint& r = out[k];
    r.lattice_constant = a;
    block_average(p, r.pressure, r.pressure_error);
    r.temperature = std::accumulate(t.begin(), t.end(), 0.0) / t.size();
  }
  return out;
}

std::vector<IsothermPoint> dpd_isotherm(const dpd::PairPotential& pot,
                                        const std::vector<double>& coarse_lattice_constants,
                                        const DpdIsothermOptions& o) {
  const int n = static_cast<int>(coarse_lattice_constants.size());
  std::vector<IsothermPoint> out(n);
#pragma omp parallel for schedule(dynamic, 1) num_threads(o.threads)
  for (int k = 0; k < n; ++k) {
    const double a = coarse_lattice_constants[k];
    dpd::Particles p = dpd::fcc_block({o.cells, o.cells, o.cells}, a, {0, 0, 0}, o.mass, 0, 1);
    dpd::maxwell_velocities(p, 2 * o.temperature, o.seed + static_cast<std::uint64_t>(k));
    for (auto& u : p.u) u = o.heat_capacity * o.temperature;
    dpd::DpdParams par;
    par.energy_conserving = true;
    par.gamma = o.gamma;
    par.cutoff = dpd::cutoff(pot);
    par.heat_capacity = o.heat_capacity;
    par.seed = o.seed + 1000 + static_cast<std::uint64_t>(k);
    dpd::Domain d;
    d.box.lx = d.box.ly = d.box.lz = o.cells * a;
    dpd::System s(std::move(p), d, pot, par, {.skin = o.skin, .threads = 1});
    const dpd::Berendsen b{.temperature = o.temperature, .tau = o.berendsen_tau};
    s.advance(o.equilibrate_steps, o.dt, &b);
    std::vector<double> pr, t;
    for (int done = 0; done < o.sample_steps; done += 10) {
      s.advance(10, o.dt);
      pr.push_back(s.pressure_gpa());
      t.push_back(s.temperature());
    }
    IsothermPoint& r = out[k];
    r.lattice_constant = a;
    block_average(pr, r.pressure, r.pressure_error);
    r.temperature = std::accumulate(t.begin(), t.end(), 0.0) / t.size();
  }
  return out;
}

double static_lattice_pressure(const dpd::PairPotential& pot, double a) {
  const double rc = dpd::cutoff(pot), rc2 = rc * rc;
  // As the Born sums (dpd/elastic.cpp): at most 100 cells per axis, and the count an int.
  if (!(a > 0) || !(rc / a <= 100))
    throw InputError(fmt::format("static lattice pressure: lattice constant {} A against a cutoff of {} A: the "
                                 "lattice sum would run over more than 100 cells per axis",
                                 a, rc));
  const int m = static_cast<int>(std::ceil(rc / a)) + 1;
  double w = 0;  // sum over lattice vectors of r F(r) = r^2 (F/r)
  std::visit(
      [&](const auto& pp) {
        for (int i = -m; i <= m; ++i)
          for (int j = -m; j <= m; ++j)
            for (int k = -m; k <= m; ++k)
              for (const auto& b : particles::kFccBasis) {
                const double x = (i + b[0]) * a, y = (j + b[1]) * a, z = (k + b[2]) * a;
                const double r2 = x * x + y * y + z * z;
                if (r2 == 0 || r2 >= rc2) continue;
                double e, fr;
                pp.eval(r2, e, fr);
                w += r2 * fr;
              }
      },
      pot);
  const double omega = a * a * a / 4.0;
  return 0.5 * w / (3.0 * omega) * units::eV_per_A3_in_GPa;
}

double zero_pressure_density(const std::vector<double>& rho, const std::vector<double>& p) {
  std::vector<std::size_t> order(rho.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rho[a] < rho[b]; });
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    const double r0 = rho[order[k]], r1 = rho[order[k + 1]], p0 = p[order[k]], p1 = p[order[k + 1]];
    if ((p0 <= 0 && p1 >= 0) || (p0 >= 0 && p1 <= 0)) {
      if (p1 == p0) return r0;
      return r0 + (r1 - r0) * (0 - p0) / (p1 - p0);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace mpmx::multiscale
