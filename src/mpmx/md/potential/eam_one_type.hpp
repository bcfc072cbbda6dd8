#pragma once
// The EAM force loop for one element (the common case: pure metals), with its vector
// forms written once (Google Highway) and compiled for every path of the 1-D kernels'
// targets (core/simd_targets.hpp); each call takes the path the 1-D kernels take (the
// best this machine has, or MPMX_ISA's). Every path gives the scalar loop's bits.
#include <string>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

// Force-pass record per knot: rho c0..c2, z2r c0..c6 (unpadded: a smaller table beats
// line alignment, an 80-byte record touches two lines either way).
constexpr int kEamPairStride = 10;

// The tables of one element: per knot the density-pass record (rho c3..c6) and the
// force-pass record; F(rho) as 7 coefficients per knot (eam.hpp).
template <class Real>
struct EamOneType {
  const Real* rho_tab;
  const Real* pair_tab;
  const double* frho;
  int nr, nrho;
  double rdr, rdrho, rhomax, cut;
};

// Same arithmetic as pair_eam for Real = double; float pairs with double sums else.
ForceSums eam_one_type(const EamOneType<double>& t, const Neighbors& nb, ForceWork& w);
ForceSums eam_one_type(const EamOneType<float>& t, const Neighbors& nb, ForceWork& w);

// The path the kernel's dispatch takes now, as the kernel itself reports it (tests).
std::string eam_isa_dispatched();
// "MD kernels: paths ...; this machine: ...; chosen: ...", for `mpmx --version`.
std::string eam_isa_summary();

}  // namespace mpmx::md
