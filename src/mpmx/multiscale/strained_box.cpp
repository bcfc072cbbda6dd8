#include "mpmx/multiscale/strained_box.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/dpd/setup.hpp"
#include "mpmx/dpd/system.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/multiscale/batch.hpp"
#include "mpmx/multiscale/isotherm.hpp"
#include "mpmx/particles/lattice.hpp"

namespace mpmx::multiscale {

namespace {

// The time-averaged stresses a strained box is measured by: sigma_xx, the mean of
// sigma_yy and sigma_zz, and the pressure.
struct BoxStress {
  double xx = 0, xx_error = 0;
  double yy = 0, yy_error = 0;
  double pressure = 0;
};

struct StressSeries {
  std::vector<double> xx, yy, p;
  void add(const particles::Mat3& s) {
    xx.push_back(s[0]);
    yy.push_back(0.5 * (s[4] + s[8]));
    p.push_back(mean_pressure(s));
  }
  BoxStress mean() const {
    BoxStress b;
    double p_error = 0;
    block_average(xx, b.xx, b.xx_error);
    block_average(yy, b.yy, b.yy_error);
    block_average(p, b.pressure, p_error);
    return b;
  }
};

BoxStress static_stress(const particles::Mat3& s) {
  return {.xx = s[0], .yy = 0.5 * (s[4] + s[8]), .pressure = mean_pressure(s)};
}

double strain_of(const StrainedBoxOptions& o) {
  if (o.strain > 0) return o.strain;
  return o.temperature > 0 ? 0.01 : 1e-4;
}

void check(const StrainedBoxOptions& o, double a) {
  if (!(a > 0) || o.cells < 1 || !(o.temperature >= 0) || !(o.strain >= 0 && o.strain < 0.2))
    throw InputError("strained boxes: the lattice constant, cells, temperature or strain is out of range");
}

// Boxes 0, 1, 2: strained by -e, 0, +e. The prestress terms make the Cauchy slopes the
// Green-strain constants (see the header).
CubicConstants constants_from(const std::array<BoxStress, 3>& b, double e) {
  CubicConstants c;
  c.strain = e;
  c.pressure = b[1].pressure;
  c.c11 = (b[2].xx - b[0].xx) / (2 * e) + c.pressure;
  c.c12 = (b[2].yy - b[0].yy) / (2 * e) - c.pressure;
  c.c11_error = std::hypot(b[2].xx_error, b[0].xx_error) / (2 * e);
  c.c12_error = std::hypot(b[2].yy_error, b[0].yy_error) / (2 * e);
  return c;
}

}  // namespace

CubicConstants md_strained_constants(const md::Potential& pot, double a, const StrainedBoxOptions& o) {
  check(o, a);
  const double e = strain_of(o);
  const int n = o.cells;
  std::array<BoxStress, 3> b;
  if (o.temperature == 0) {
    Batch(o.threads).for_each(3, [&](std::size_t k) {
      md::System s(particles::fcc(n, n, n, a, (static_cast<int>(k) - 1) * e), pot);
      s.refresh();
      b[k] = static_stress(s.stress_gpa());
    });
    return constants_from(b, e);
  }
  md::System base(particles::fcc(n, n, n, a), pot);
  base.thermalize(o.temperature, o.seed, 0);
  advance_at_temperature(base, o.equilibrate_steps, o.dt, o.temperature);
  Batch(o.threads).for_each(3, [&](std::size_t k) {
    md::System s = base;
    const double f = 1.0 + (static_cast<int>(k) - 1) * e;  // the affine map x -> (1 + e) x keeps every image in step
    particles::Atoms& at = s.edit_atoms();
    for (auto& x : at.x) x *= f;
    particles::Box box = s.box();
    box.lx *= f;
    s.set_box(box);
    advance_at_temperature(s, o.equilibrate_steps / 2, o.dt, o.temperature);
    StressSeries series;
    for (int done = 0; done < o.sample_steps; done += 10) {
      s.advance(10, o.dt);
      series.add(s.stress_gpa());
      if ((done + 10) % 50 == 0) rescale_temperature(s, o.temperature);
    }
    b[k] = series.mean();
  });
  return constants_from(b, e);
}

TensorAtTemperature md_strained_tensor(const md::Potential& pot, const particles::LatticeSpec& spec,
                                       const std::array<int, 3>& tiles, const StrainedBoxOptions& o) {
  check(o, spec.constant);
  if (!(o.temperature > 0)) throw InputError("a tensor at a temperature needs one above 0 K");
  const double e = strain_of(o);
  md::System base(particles::oriented_crystal(spec, tiles), pot);
  base.thermalize(o.temperature, o.seed, 0);
  advance_at_temperature(base, o.equilibrate_steps, o.dt, o.temperature);
  // Box 2 j + (0, 1): component j strained by -e, +e; box 12 unstrained.
  std::array<std::array<double, 6>, 13> mean{}, error{};
  Batch(o.threads).for_each(13, [&](std::size_t k) {
    md::System s = base;
    if (k < 12) {
      particles::Atoms& at = s.edit_atoms();
      particles::Box box = s.box();
      md::strain_voigt(at, box, static_cast<int>(k / 2), k % 2 ? e : -e);
      s.set_box(box);
    }
    advance_at_temperature(s, o.equilibrate_steps / 2, o.dt, o.temperature);
    std::array<std::vector<double>, 6> series;
    for (int done = 0; done < o.sample_steps; done += 10) {
      s.advance(10, o.dt);
      const auto v = md::voigt_stress(s.stress_gpa());
      for (int c = 0; c < 6; ++c) series[c].push_back(v[c]);
      if ((done + 10) % 50 == 0) rescale_temperature(s, o.temperature);
    }
    for (int c = 0; c < 6; ++c) block_average(series[c], mean[k][c], error[k][c]);
  });
  TensorAtTemperature t;
  t.strain = e;
  t.stress = mean[12];
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      t.c[i][j] = (mean[2 * j + 1][i] - mean[2 * j][i]) / (2 * e);
      t.error[i][j] = std::hypot(error[2 * j + 1][i], error[2 * j][i]) / (2 * e);
    }
  return t;
}

CubicConstants dpd_strained_constants(const dpd::PairPotential& pot, double a, const StrainedBoxOptions& o) {
  check(o, a);
  const double e = strain_of(o);
  const int n = o.cells;
  const bool thermal = o.temperature > 0;
  if (thermal && !(o.heat_capacity > 0 && o.mass > 0 && o.gamma > 0))
    throw InputError("strained DPDE boxes: the mass, gamma and heat capacity must be positive");
  dpd::DpdParams par;
  par.energy_conserving = thermal;  // static boxes: conservative forces only
  par.gamma = o.gamma;
  par.cutoff = dpd::cutoff(pot);
  par.heat_capacity = o.heat_capacity;
  dpd::Particles start = dpd::fcc_block({n, n, n}, a, {0, 0, 0}, o.mass, 0, 1);
  dpd::Domain d;
  d.box.lx = d.box.ly = d.box.lz = n * a;
  if (thermal) {
    dpd::maxwell_velocities(start, 2 * o.temperature, o.seed);
    for (auto& u : start.u) u = o.heat_capacity * o.temperature;
    par.seed = o.seed + 1000;
    dpd::System s(std::move(start), d, pot, par);
    const dpd::Berendsen bt{.temperature = o.temperature, .tau = o.berendsen_tau};
    s.advance(o.equilibrate_steps, o.dt, &bt);
    start = s.particles();
  }
  std::array<BoxStress, 3> b;
  Batch(o.threads).for_each(3, [&](std::size_t k) {
    const double f = 1.0 + (static_cast<int>(k) - 1) * e;
    dpd::Particles p = start;
    for (auto& x : p.x) x *= f;
    dpd::Domain dk = d;
    dk.box.lx *= f;
    dpd::DpdParams pk = par;
    pk.seed = o.seed + 2000 + k;
    dpd::System s(std::move(p), dk, pot, pk);
    if (!thermal) {
      b[k] = static_stress(s.stress_gpa());
      return;
    }
    const dpd::Berendsen bt{.temperature = o.temperature, .tau = o.berendsen_tau};
    s.advance(o.equilibrate_steps / 2, o.dt, &bt);  // isothermal constants, as the MD boxes'
    StressSeries series;
    for (int done = 0; done < o.sample_steps; done += 10) {
      s.advance(10, o.dt);
      series.add(s.stress_gpa());
    }
    b[k] = series.mean();
  });
  return constants_from(b, e);
}

}  // namespace mpmx::multiscale
