#include "mpmx/dpd/forces.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include "mpmx/core/units.hpp"
#include "mpmx/dpd/pair_random.hpp"

namespace mpmx::dpd {

namespace {

// Pairs closer than this are skipped (coincident soft particles; LAMMPS pair dpd does the same).
constexpr double kMinR2 = 1e-20;

// Pair forces of every slot into the buffer; each particle's own slots summed into its
// force (the partner's share is subtracted by the gather); energy and virial per
// particle when Tally.
template <class Pot, bool Stochastic, bool Tally>
void pair_pass(const Pot& pot, const PairList& list, Particles& p, const StochasticForces& st, ForceBuffers& buf,
               int threads, const std::uint8_t* no_pair) {
  const md::Neighbors& nb = list.nb;
  const int n = nb.nlocal;
  const double* __restrict q = nb.xyz.data();
  const int* __restrict first = nb.first.data();
  const int* __restrict entries = nb.list.data();
  const int* __restrict owner = nb.owner.data();
  double* __restrict pf = buf.pair_force.data();
  double* __restrict en = buf.energy.data();
  double* __restrict vir = buf.virial.data();
  double* __restrict fx = p.fx.data();
  double* __restrict fy = p.fy.data();
  double* __restrict fz = p.fz.data();
  const double rcc = pot.cutoff(), rcc2 = rcc * rcc;
  const double rcd = st.cutoff, rcd2 = Stochastic ? rcd * rcd : 0.0;
  const double rmax2 = std::max(rcc2, rcd2);
  // eV/Angstrom from amu Angstrom/ps^2: F^D = -gamma_e w^2 (e.v), F^R = sigma_e w theta.
  const double gamma_e = st.gamma * units::mvv2e;
  const double sigma_e = std::sqrt(2.0 * st.gamma * units::boltzmann_eV_per_K * st.temperature / units::mvv2e) *
                         units::mvv2e / std::sqrt(st.dt);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int i = 0; i < n; ++i) {
    const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
    double e_i = 0, wxx = 0, wyy = 0, wzz = 0, wxy = 0, wxz = 0, wyz = 0;
    double sx = 0, sy = 0, sz = 0;
    const bool masked = no_pair && no_pair[i];
    for (int s = first[i]; s < first[i + 1]; ++s) {
      const int k = entries[s];
      const double dx = xi - q[4 * k], dy = yi - q[4 * k + 1], dz = zi - q[4 * k + 2];
      const double r2 = dx * dx + dy * dy + dz * dz;
      double fr = 0.0;
      if (r2 < rmax2 && r2 >= kMinR2 && !(masked && no_pair[owner[k]])) {
        if (r2 < rcc2) {
          double e;
          pot.eval(r2, e, fr);
          if constexpr (Tally) e_i += e;
        }
        if constexpr (Stochastic) {
          if (r2 < rcd2) {
            const int j = owner[k];
            const double r = std::sqrt(r2), w = 1.0 - r / rcd;
            const double dot = (dx * (p.vx[i] - p.vx[j]) + dy * (p.vy[i] - p.vy[j]) + dz * (p.vz[i] - p.vz[j])) / r;
            const double theta =
                pair_normal(pair_key(st.seed, st.step, p.id[i], p.id[j], nb.n1[k], nb.n2[k], nb.n3[k]));
            fr += (-gamma_e * w * w * dot + sigma_e * w * theta) / r;
          }
        }
      }
      const double px = fr * dx, py = fr * dy, pz = fr * dz;
      pf[3 * s] = px, pf[3 * s + 1] = py, pf[3 * s + 2] = pz;
      sx += px, sy += py, sz += pz;
      if constexpr (Tally) {
        wxx += dx * px, wyy += dy * py, wzz += dz * pz;
        wxy += dx * py, wxz += dx * pz, wyz += dy * pz;
      }
    }
    fx[i] = sx, fy[i] = sy, fz[i] = sz;
    if constexpr (Tally) {
      en[i] = e_i;
      double* w = vir + 6 * i;
      w[0] = wxx, w[1] = wyy, w[2] = wzz, w[3] = wxy, w[4] = wxz, w[5] = wyz;
    }
  }
}

}  // namespace

md::ForceSums compute_pair_forces(const PairPotential& pot, const PairList& list, Particles& p,
                                  const StochasticForces* stochastic, ForceBuffers& buf, int threads, bool tally,
                                  const std::uint8_t* no_pair) {
  const int n = list.nb.nlocal;
  buf.pair_force.resize(3 * static_cast<std::size_t>(list.slots()));
  buf.energy.resize(n);
  buf.virial.resize(6 * static_cast<std::size_t>(n));
  const StochasticForces none{};
  std::visit(
      [&](const auto& pp) {
        using P = std::decay_t<decltype(pp)>;
        const bool st = stochastic && stochastic->gamma > 0;
        if (st && tally) pair_pass<P, true, true>(pp, list, p, *stochastic, buf, threads, no_pair);
        else if (st) pair_pass<P, true, false>(pp, list, p, *stochastic, buf, threads, no_pair);
        else if (tally) pair_pass<P, false, true>(pp, list, p, none, buf, threads, no_pair);
        else pair_pass<P, false, false>(pp, list, p, none, buf, threads, no_pair);
      },
      pot);

  // Each particle, its own slots summed, takes the slots where it is the partner.
  const int* __restrict tfirst = list.nb.tfirst.data();
  const int* __restrict tslot = list.nb.tslot.data();
  const double* __restrict pf = buf.pair_force.data();
  double* __restrict fx = p.fx.data();
  double* __restrict fy = p.fy.data();
  double* __restrict fz = p.fz.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int j = 0; j < n; ++j) {
    double sx = fx[j], sy = fy[j], sz = fz[j];
    for (int t = tfirst[j]; t < tfirst[j + 1]; ++t) {
      const int s = tslot[t];
      sx -= pf[3 * s], sy -= pf[3 * s + 1], sz -= pf[3 * s + 2];
    }
    fx[j] = sx, fy[j] = sy, fz[j] = sz;
  }

  md::ForceSums sums;
  if (!tally) return sums;
  for (int i = 0; i < n; ++i) {
    sums.energy += buf.energy[i];
    for (int c = 0; c < 6; ++c) sums.virial[c] += buf.virial[6 * i + c];
  }
  return sums;
}

}  // namespace mpmx::dpd
