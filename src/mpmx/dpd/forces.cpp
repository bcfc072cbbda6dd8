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

// Pair forces tile by tile (particles::Neighbors tiles: runs of consecutive particles):
// each pair's force added to its particle i's sum and taken from its partner's entry in the
// tile's own force array (3 per entry of the tile, small enough for a core's cache);
// energy and virial per particle i when Tally. Which thread takes which tile changes
// no number.
template <class Pot, bool Stochastic, bool Tally>
void pair_pass(const Pot& pot, const PairList& list, const Particles& p, const StochasticForces& st, ForceBuffers& buf,
               int threads, const std::uint8_t* no_pair) {
  const particles::Neighbors& nb = list.nb;
  const int ntile = static_cast<int>(nb.tile_atom.size()) - 1;
  const double* __restrict q = nb.xyz.data();
  const int* __restrict first = nb.first.data();
  const int* __restrict entries = nb.list.data();
  const int* __restrict place = nb.tile_list.data();
  const int* __restrict owner = nb.owner.data();
  double* __restrict tf = buf.tile_force.data();
  double* __restrict en = buf.energy.data();
  double* __restrict vir = buf.virial.data();
  const double rcc = pot.cutoff(), rcc2 = rcc * rcc;
  const double rcd = st.cutoff, rcd2 = Stochastic ? rcd * rcd : 0.0;
  const double rmax2 = std::max(rcc2, rcd2);
  // eV/Angstrom from amu Angstrom/ps^2: F^D = -gamma_e w^2 (e.v), F^R = sigma_e w theta.
  const double gamma_e = st.gamma * units::mvv2e;
  const double sigma_e = std::sqrt(2.0 * st.gamma * units::boltzmann_eV_per_K * st.temperature / units::mvv2e) *
                         units::mvv2e / std::sqrt(st.dt);
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (int t = 0; t < ntile; ++t) {
    const int a = nb.tile_atom[t], b = nb.tile_atom[t + 1], u0 = nb.tile_first[t];
    double* __restrict f = tf + 3 * static_cast<std::size_t>(u0);
    std::fill_n(f, 3 * static_cast<std::size_t>(nb.tile_first[t + 1] - u0), 0.0);
    for (int i = a; i < b; ++i) {
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
        double* fk = f + 3 * place[s];
        fk[0] -= px, fk[1] -= py, fk[2] -= pz;
        sx += px, sy += py, sz += pz;
        if constexpr (Tally) {
          wxx += dx * px, wyy += dy * py, wzz += dz * pz;
          wxy += dx * py, wxz += dx * pz, wyz += dy * pz;
        }
      }
      double* fi = f + 3 * (i - a);
      fi[0] += sx, fi[1] += sy, fi[2] += sz;
      if constexpr (Tally) {
        en[i] = e_i;
        double* w = vir + 6 * i;
        w[0] = wxx, w[1] = wyy, w[2] = wzz, w[3] = wxy, w[4] = wxz, w[5] = wyz;
      }
    }
  }
}

}  // namespace

particles::ForceSums compute_pair_forces(const PairPotential& pot, const PairList& list, Particles& p,
                                  const StochasticForces* stochastic, ForceBuffers& buf, int threads, bool tally,
                                  const std::uint8_t* no_pair) {
  const int n = list.nb.nlocal;
  buf.tile_force.resize(3 * list.nb.tile_entry.size());
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

  // Each particle adds its shares from every tile, in tile order.
  const int* __restrict share_first = list.nb.share_first.data();
  const int* __restrict share = list.nb.share.data();
  const double* __restrict tf = buf.tile_force.data();
  double* __restrict fx = p.fx.data();
  double* __restrict fy = p.fy.data();
  double* __restrict fz = p.fz.data();
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int j = 0; j < n; ++j) {
    double sx = 0, sy = 0, sz = 0;
    for (int v = share_first[j]; v < share_first[j + 1]; ++v) {
      const double* f = tf + 3 * static_cast<std::size_t>(share[v]);
      sx += f[0], sy += f[1], sz += f[2];
    }
    fx[j] = sx, fy[j] = sy, fz[j] = sz;
  }

  particles::ForceSums sums;
  if (!tally) return sums;
  for (int i = 0; i < n; ++i) {
    sums.energy += buf.energy[i];
    for (int c = 0; c < 6; ++c) sums.virial[c] += buf.virial[6 * i + c];
  }
  return sums;
}

}  // namespace mpmx::dpd
