#include "mpmx/dpd/shardlow.hpp"

#include <cmath>
#include <limits>

#include "mpmx/core/units.hpp"
#include "mpmx/dpd/pair_random.hpp"

namespace mpmx::dpd {

namespace {

template <bool Dpde>
void sweep(const PairList& list, Particles& p, const SweepParams& sp, SweepWork& work, int threads) {
  const particles::Neighbors& nb = list.nb;
  const int n = nb.nlocal;
  const double* __restrict q = nb.xyz.data();
  const int* __restrict slot_i = list.slot_i.data();
  const int* __restrict entries = nb.list.data();
  const int* __restrict owner = nb.owner.data();
  const std::int8_t* __restrict n1 = nb.n1.data();
  const std::int8_t* __restrict n2 = nb.n2.data();
  const std::int8_t* __restrict n3 = nb.n3.data();
  const std::int64_t* __restrict id = p.id.data();
  const int* __restrict sweep_slots = list.sweep.data();
  const int* __restrict slab_first = list.slab_first.data();
  const double rc = sp.cutoff, rc2 = rc * rc, inv_rc = 1.0 / rc;
  const double sqdt = std::sqrt(sp.dt);
  const double half_gamma_dt = 0.5 * sp.gamma * sp.dt;
  // sigma in amu Angstrom ps^-3/2 is sqrt(2 gamma kB T / mvv2e).
  const double kb_amu = units::boltzmann_eV_per_K / units::mvv2e;
  // R = sigma_ij w sqrt(dt) theta / 2 = c_sigma sqrt(T_ij) w theta, and with
  // T_ij = 2 / (1/T_i + 1/T_j): R = c_sigma sqrt(2 / s_ij) w theta.
  const double c_sigma = 0.5 * std::sqrt(2.0 * sp.gamma * kb_amu) * sqdt;
  const double half_sigma_iso = c_sigma * std::sqrt(sp.temperature);
  work.inv_mass.resize(n);
  work.inv_temperature.resize(n);
  double* __restrict inv_m = work.inv_mass.data();
  double* __restrict inv_t = work.inv_temperature.data();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int i = 0; i < n; ++i) {
    inv_m[i] = p.group[i] == kMobile ? 1.0 / p.mass[i] : 0.0;
    if constexpr (Dpde) inv_t[i] = p.u[i] > 0 ? sp.heat_capacity / p.u[i] : std::numeric_limits<double>::infinity();
  }
  double* __restrict vx = p.vx.data();
  double* __restrict vy = p.vy.data();
  double* __restrict vz = p.vz.data();
  double* __restrict u = p.u.data();
#pragma omp parallel num_threads(threads)
  for (int f = 0; f < PairList::kPhases; ++f) {
#pragma omp for schedule(dynamic, 1)
    for (int b = list.phase_first[f]; b < list.phase_first[f + 1]; ++b) {
      // Runs of pairs of one particle i (slots are grouped by i): i's velocity and
      // internal energy stay in registers over its run (no pair of the run has j = i).
      for (int t = slab_first[b]; t < slab_first[b + 1];) {
        const int i = slot_i[sweep_slots[t]];
        double vxi = vx[i], vyi = vy[i], vzi = vz[i], ui = u[i];
        const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2], mi = inv_m[i], ti = inv_t[i];
        const std::int64_t idi = id[i];
        for (; t < slab_first[b + 1] && slot_i[sweep_slots[t]] == i; ++t) {
          const int s = sweep_slots[t];
          const int k = entries[s], j = owner[k];
          const double dx = xi - q[4 * k], dy = yi - q[4 * k + 1], dz = zi - q[4 * k + 2];
          const double r2 = dx * dx + dy * dy + dz * dz;
          if (r2 >= rc2 || r2 < 1e-20) continue;
          const double mj = inv_m[j], msum = mi + mj;
          if (msum == 0.0) continue;  // two rigid particles
          const double r = std::sqrt(r2), rinv = 1.0 / r;
          const double ex = dx * rinv, ey = dy * rinv, ez = dz * rinv;
          const double w = 1.0 - r * inv_rc;
          double half_sigma = half_sigma_iso;
          if constexpr (Dpde) half_sigma = c_sigma * std::sqrt(2.0 / (ti + inv_t[j]));  // T_ij = 0 if a u <= 0
          const double theta = pair_normal(pair_key(sp.seed, sp.step, idi, id[j], n1[k], n2[k], n3[k]));
          const double rr = half_sigma * w * theta;  // impulse, amu Angstrom/ps
          const double gg = half_gamma_dt * w * w;  // amu
          // The explicit half A = R - G g0 and the implicit half B = (R - G g1) / (1 + G msum),
          // g1 = g0 + A msum, add up to the impulse P = A + B = 2 (R - G g0) / (1 + G msum).
          const double kk = 2.0 / (1.0 + msum * gg);
          const double g0 = ex * (vxi - vx[j]) + ey * (vyi - vy[j]) + ez * (vzi - vz[j]);
          const double imp = kk * (rr - gg * g0);
          vxi += ex * imp * mi, vyi += ey * imp * mi, vzi += ez * imp * mi;
          vx[j] -= ex * imp * mj, vy[j] -= ey * imp * mj, vz[j] -= ez * imp * mj;
          if constexpr (Dpde) {
            const double g2 = g0 + imp * msum;                         // e . v_ij after the update
            const double dk = 0.5 * imp * (g0 + g2) * units::mvv2e;  // the pair's kinetic energy change, eV
            ui -= 0.5 * dk;
            u[j] -= 0.5 * dk;
          }
        }
        vx[i] = vxi, vy[i] = vyi, vz[i] = vzi, u[i] = ui;
      }
    }
  }
}

}  // namespace

void shardlow_sweep(const PairList& list, Particles& p, const SweepParams& sp, SweepWork& work, int threads) {
  if (!(sp.gamma > 0)) return;
  if (sp.energy_conserving) sweep<true>(list, p, sp, work, threads);
  else sweep<false>(list, p, sp, work, threads);
}

}  // namespace mpmx::dpd
