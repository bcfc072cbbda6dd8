#pragma once
// The EAM force loop (eqs. 5.21-5.24) over a half neighbour list, generic in the
// functions (tabulated splines or analytic Sutton-Chen) and in the floating type of
// the pair arithmetic (double, or float with double accumulation).
//   rho_i = sum_j rho_j(r_ij),  E = sum_i F_i(rho_i) + 1/2 sum_ij phi_ij(r_ij)
//   f_ij = -(F_i' rho_j'(r) + F_j' rho_i'(r) + phi'(r)) r_ij / r   (f_ij = -f_ji)
#include <algorithm>
#include <cmath>
#include <vector>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/potential/tile_shares.hpp"

namespace mpmx::md {

template <class Real, class Fn>
ForceSums eam_compute_tiles(const Fn& fn, const Neighbors& nb, ForceWork& w);

// Fn: density(r, ti, tj, at_i, at_j); embed(rho, t, F, Fp); pair(r, ti, tj, fpi, fpj) ->
// returns {phi, dE/dr}; all in Real. cutsq() in double. A list with tiles (a threaded
// system) goes to eam_compute_tiles.
template <class Real, class Fn>
ForceSums eam_compute(const Fn& fn, const Neighbors& nb, ForceWork& w) {
  if (nb.tiles && nb.tile_atom.size() > 2) return eam_compute_tiles<Real>(fn, nb, w);
  w.zero_forces();
  const int nlocal = nb.nlocal;
  const double* __restrict q = nb.xyz.data();
  const int* __restrict type = nb.type.data();
  const int* __restrict first = nb.first.data();
  const int* __restrict list = nb.list.data();
  double* __restrict rho = w.rho.data();
  const Real cutsq = static_cast<Real>(fn.cutsq());

  for (int i = 0; i < nlocal; ++i) {
    const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
    const int ti = type[i];
    double rho_i = 0;
    for (int s = first[i]; s < first[i + 1]; ++s) {
      const int k = list[s];
      const Real dx = static_cast<Real>(xi - q[4 * k]);
      const Real dy = static_cast<Real>(yi - q[4 * k + 1]);
      const Real dz = static_cast<Real>(zi - q[4 * k + 2]);
      const Real rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < cutsq) {
        Real at_i, at_k;
        fn.density(std::sqrt(rsq), ti, type[k], at_i, at_k);
        rho_i += at_i;
        rho[k] += at_k;
      }
    }
    rho[i] += rho_i;
  }
  nb.fold(w.rho);

  ForceSums sums;
  double embed = 0;
  for (int i = 0; i < nlocal; ++i) {
    double F, Fp;
    fn.embed(rho[i], type[i], F, Fp);
    w.fp[i] = Fp;
    embed += F;
    if (w.per_atom) w.energy_atom[i] += F;
  }
  nb.forward(w.fp);

  const double* __restrict fp = w.fp.data();
  double* __restrict fx = w.fx.data();
  double* __restrict fy = w.fy.data();
  double* __restrict fz = w.fz.data();
  double epair = 0, vxx = 0, vyy = 0, vzz = 0, vxy = 0, vxz = 0, vyz = 0;
  for (int i = 0; i < nlocal; ++i) {
    const double xi = q[4 * i], yi = q[4 * i + 1], zi = q[4 * i + 2];
    const int ti = type[i];
    const Real fpi = static_cast<Real>(fp[i]);
    double fxi = 0, fyi = 0, fzi = 0;
    for (int s = first[i]; s < first[i + 1]; ++s) {
      const int k = list[s];
      const Real dx = static_cast<Real>(xi - q[4 * k]);
      const Real dy = static_cast<Real>(yi - q[4 * k + 1]);
      const Real dz = static_cast<Real>(zi - q[4 * k + 2]);
      const Real rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < cutsq) {
        const Real r = std::sqrt(rsq);
        Real phi, dedr;
        fn.pair(r, ti, type[k], fpi, static_cast<Real>(fp[k]), phi, dedr);
        const Real fpair = -dedr / r;
        const double ffx = dx * fpair, ffy = dy * fpair, ffz = dz * fpair;
        fxi += ffx;
        fyi += ffy;
        fzi += ffz;
        fx[k] -= ffx;
        fy[k] -= ffy;
        fz[k] -= ffz;
        epair += phi;
        const double vx = dx * ffx, vy = dy * ffy, vz = dz * ffz;
        const double wxy = dx * ffy, wxz = dx * ffz, wyz = dy * ffz;
        vxx += vx, vyy += vy, vzz += vz, vxy += wxy, vxz += wxz, vyz += wyz;
        if (w.per_atom) {
          w.energy_atom[i] += 0.5 * phi;
          w.energy_atom[k] += 0.5 * phi;
          const double v6[6] = {vx, vy, vz, wxy, wxz, wyz};
          for (int c = 0; c < 6; ++c) {
            w.virial_atom[6 * i + c] += 0.5 * v6[c];
            w.virial_atom[6 * k + c] += 0.5 * v6[c];
          }
        }
      }
    }
    fx[i] += fxi;
    fy[i] += fyi;
    fz[i] += fzi;
  }
  sums.energy = embed + epair;
  sums.virial = {vxx, vyy, vzz, vxy, vxz, vyz};
  return sums;
}

// The same passes on w.threads threads over the list's tiles (Neighbors::tiles,
// tile_shares.hpp): every thread count gives the same bits.
template <class Real, class Fn>
ForceSums eam_compute_tiles(const Fn& fn, const Neighbors& nb, ForceWork& w) {
  const int nlocal = nb.nlocal;
  const int ntile = static_cast<int>(nb.tile_atom.size()) - 1;
  const std::size_t ne = nb.tile_entry.size();
  const int* __restrict tile_atom = nb.tile_atom.data();
  const int* __restrict tile_first = nb.tile_first.data();
  const int* __restrict tile_entry = nb.tile_entry.data();
  const int* __restrict tile_list = nb.tile_list.data();
  const int* __restrict first = nb.first.data();
  const int* __restrict owner = nb.owner.data();
  const int* __restrict type = nb.type.data();
  const double* __restrict xyz = nb.xyz.data();
  const Real cutsq = static_cast<Real>(fn.cutsq());
  const bool per_atom = w.per_atom, tally = w.tally || w.per_atom;

  // Per entry of every tile: density, F', force (4 doubles); per tile: energy and virial.
  thread_local std::vector<double> trho, tfp, tf, te, tw, tsum, emb;
  trho.assign(ne, 0.0);
  tfp.resize(ne);
  tf.assign(4 * ne, 0.0);
  tsum.assign(7 * static_cast<std::size_t>(ntile), 0.0);
  emb.resize(nlocal);
  if (per_atom) te.assign(ne, 0.0), tw.assign(6 * ne, 0.0);
  double* __restrict rho_e = trho.data();
  double* __restrict fp_e = tfp.data();
  double* __restrict f_e = tf.data();
  double* __restrict sum_t = tsum.data();
  double* __restrict emb_a = emb.data();
  double* __restrict e_e = per_atom ? te.data() : nullptr;
  double* __restrict w_e = per_atom ? tw.data() : nullptr;
  double* __restrict fp = w.fp.data();
  // Atom i's pairs within the cutoff in tile p (entries from u0): body(uk, dx, dy, dz, rsq).
  auto pairs_of = [&](int i, int u0, auto&& body) {
    const double* qi = xyz + 4 * static_cast<std::size_t>(i);
    for (int s = first[i]; s < first[i + 1]; ++s) {
      const int uk = u0 + tile_list[s];
      const double* qk = xyz + 4 * static_cast<std::size_t>(tile_entry[uk]);
      const Real dx = static_cast<Real>(qi[0] - qk[0]), dy = static_cast<Real>(qi[1] - qk[1]),
                 dz = static_cast<Real>(qi[2] - qk[2]);
      const Real rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < cutsq) body(uk, dx, dy, dz, rsq);
    }
  };
  const int threads = std::max(1, w.threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
#pragma omp for schedule(dynamic)
    for (int p = 0; p < ntile; ++p) {  // each tile: the density of its pairs
      const int u0 = tile_first[p];
      for (int i = tile_atom[p]; i < tile_atom[p + 1]; ++i) {
        double rho_i = 0;
        pairs_of(i, u0, [&](int uk, Real, Real, Real, Real rsq) {
          Real at_i, at_k;
          fn.density(std::sqrt(rsq), type[i], type[tile_entry[uk]], at_i, at_k);
          rho_i += at_i;
          rho_e[uk] += at_k;
        });
        rho_e[u0 + i - tile_atom[p]] += rho_i;
      }
    }
#pragma omp for schedule(dynamic, 256)
    for (int j = 0; j < nlocal; ++j) {  // each atom: its shares of density, F and F'
      double r = 0;
      for (int v = nb.share_first[j]; v < nb.share_first[j + 1]; ++v) r += rho_e[nb.share[v]];
      w.rho[j] = r;
      fn.embed(r, type[j], emb_a[j], fp[j]);
    }
#pragma omp for schedule(dynamic)
    for (int p = 0; p < ntile; ++p) {  // each tile: the forces of its pairs and its sums
      const int u0 = tile_first[p];
      for (int u = u0; u < tile_first[p + 1]; ++u) fp_e[u] = fp[owner[tile_entry[u]]];
      double epair = 0, v[6] = {};
      for (int i = tile_atom[p]; i < tile_atom[p + 1]; ++i) {
        const int ui = u0 + i - tile_atom[p];
        const Real fpi = static_cast<Real>(fp_e[ui]);
        double fxi = 0, fyi = 0, fzi = 0;
        pairs_of(i, u0, [&](int uk, Real dx, Real dy, Real dz, Real rsq) {
          const Real r = std::sqrt(rsq);
          Real phi, dedr;
          fn.pair(r, type[i], type[tile_entry[uk]], fpi, static_cast<Real>(fp_e[uk]), phi, dedr);
          const Real fpair = -dedr / r;
          const double ffx = dx * fpair, ffy = dy * fpair, ffz = dz * fpair;
          fxi += ffx, fyi += ffy, fzi += ffz;
          f_e[4 * uk] -= ffx, f_e[4 * uk + 1] -= ffy, f_e[4 * uk + 2] -= ffz;
          if (!tally) return;
          const double v6[6] = {dx * ffx, dy * ffy, dz * ffz, dx * ffy, dx * ffz, dy * ffz};
          epair += phi;
          for (int c = 0; c < 6; ++c) v[c] += v6[c];
          if (!per_atom) return;
          e_e[ui] += 0.5 * phi, e_e[uk] += 0.5 * phi;
          for (int c = 0; c < 6; ++c) w_e[6 * ui + c] += 0.5 * v6[c], w_e[6 * uk + c] += 0.5 * v6[c];
        });
        f_e[4 * ui] += fxi, f_e[4 * ui + 1] += fyi, f_e[4 * ui + 2] += fzi;
      }
      sum_t[7 * p] = epair;
      for (int c = 0; c < 6; ++c) sum_t[7 * p + 1 + c] = v[c];
    }
#pragma omp for schedule(dynamic, 256)
    for (int j = 0; j < nlocal; ++j) gather_shares(nb, j, f_e, per_atom, emb_a[j], e_e, w_e, w);
  }
  ForceSums sums;
  if (tally) sums = sum_tiles(emb_a, nlocal, sum_t, ntile);
  w.folded = true;
  return sums;
}

}  // namespace mpmx::md
