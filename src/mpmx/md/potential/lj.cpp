#include "mpmx/md/potential/lj.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/analytic.hpp"

namespace mpmx::md {

LennardJones::LennardJones(double epsilon, double sigma, double cutoff, double mass, bool shift)
    : eps_(epsilon), sigma_(sigma), cut_(cutoff), mass_(mass) {
  if (!(epsilon > 0 && sigma > 0 && cutoff > 0 && mass > 0))
    throw InputError(fmt::format("lennard-jones: epsilon {}, sigma {}, cutoff {}, mass {}: all "
                                 "must be positive",
                                 epsilon, sigma, cutoff, mass));
  if (shift) shift_ = phi(cutoff);
}

double LennardJones::phi(double r) const {
  const double s6 = std::pow(sigma_ / r, 6);
  return 4 * eps_ * (s6 * s6 - s6) - shift_;
}

double LennardJones::dphi(double r) const {
  const double s6 = std::pow(sigma_ / r, 6);
  return -24 * eps_ * (2 * s6 * s6 - s6) / r;
}

ForceSums LennardJones::compute(const Neighbors& nb, ForceWork& w) const {
  w.zero_forces();
  ForceSums s;
  const double cutsq = cut_ * cut_, s2 = sigma_ * sigma_;
  for (int i = 0; i < nb.nlocal; ++i) {
    for (int s_ = nb.first[i]; s_ < nb.first[i + 1]; ++s_) {
      const int k = nb.list[s_];
      const double* q = nb.xyz.data();
      const double dx = q[4 * i] - q[4 * k], dy = q[4 * i + 1] - q[4 * k + 1], dz = q[4 * i + 2] - q[4 * k + 2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq >= cutsq) continue;
      const double sr2 = s2 / rsq, sr6 = sr2 * sr2 * sr2;
      const double fpair = 24 * eps_ * (2 * sr6 * sr6 - sr6) / rsq;  // -phi'(r)/r
      const double e = 4 * eps_ * (sr6 * sr6 - sr6) - shift_;
      const double v6[6] = {dx * dx * fpair, dy * dy * fpair, dz * dz * fpair,
                            dx * dy * fpair, dx * dz * fpair, dy * dz * fpair};
      w.fx[i] += dx * fpair, w.fy[i] += dy * fpair, w.fz[i] += dz * fpair;
      w.fx[k] -= dx * fpair, w.fy[k] -= dy * fpair, w.fz[k] -= dz * fpair;
      s.energy += e;
      for (int c = 0; c < 6; ++c) s.virial[c] += v6[c];
      if (w.per_atom) {
        w.energy_atom[i] += 0.5 * e;
        w.energy_atom[k] += 0.5 * e;
        for (int c = 0; c < 6; ++c) {
          w.virial_atom[6 * i + c] += 0.5 * v6[c];
          w.virial_atom[6 * k + c] += 0.5 * v6[c];
        }
      }
    }
  }
  return s;
}

LjSpec LjSpec::read(Table& t, const std::string& /*deck_dir*/) {
  LjSpec s;
  read_analytic_scale(t, s.epsilon, s.cutoff, s.mass);
  s.sigma = t.number("sigma");
  t.positive("sigma", s.sigma);
  s.shift = t.boolean("shift", false);
  return s;
}

std::string LjSpec::lammps_pair_lines(const LennardJones& /*made*/) const {
  return fmt::format("pair_style lj/cut {:.17g}\npair_coeff * * {:.17g} {:.17g}\n{}", cutoff, epsilon, sigma,
                     shift ? "pair_modify shift yes\n" : "");
}

}  // namespace mpmx::md
