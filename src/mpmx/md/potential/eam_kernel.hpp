#pragma once
// The EAM force loop (eqs. 5.21-5.24) over a half neighbour list, generic in the
// functions (tabulated splines or analytic Sutton-Chen) and in the floating type of
// the pair arithmetic (double, or float with double accumulation).
//   rho_i = sum_j rho_j(r_ij),  E = sum_i F_i(rho_i) + 1/2 sum_ij phi_ij(r_ij)
//   f_ij = -(F_i' rho_j'(r) + F_j' rho_i'(r) + phi'(r)) r_ij / r   (f_ij = -f_ji)
#include <cmath>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// Fn: density(r, ti, tj, at_i, at_j); embed(rho, t, F, Fp); pair(r, ti, tj, fpi, fpj) ->
// returns {phi, dE/dr}; all in Real. cutsq() in double.
template <class Real, class Fn>
ForceSums eam_compute(const Fn& fn, const Neighbors& nb, ForceWork& w) {
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

}  // namespace mpmx::md
