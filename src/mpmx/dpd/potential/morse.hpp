#pragma once
// Morse pair potential for coarse-grained solids (the Cu mesoparticle model of D0: a
// minimum at r0 of depth D0 and a repulsive core), cut at rc and shifted to zero there
// (LAMMPS `pair_style morse` with `pair_modify shift yes`):
//   U(r) = D0 [exp(-2 alpha (r - r0)) - 2 exp(-alpha (r - r0))] - U_raw(rc),
//   F(r) = -dU/dr = 2 alpha D0 [exp(-2 alpha (r - r0)) - exp(-alpha (r - r0))].
// Deck: style = "morse", d0 (eV), alpha (1/Angstrom), r0 (Angstrom), cutoff, shift.
#include <cmath>
#include <string>
#include <string_view>

#include "mpmx/core/table.hpp"

namespace mpmx::dpd {

struct MorsePotential {
  static constexpr std::string_view name = "morse";
  double d0 = 0, alpha = 1, r0 = 1, rc = 1;
  bool shift = true;
  double offset = 0;  // U_raw(rc) when shifted

  double cutoff() const { return rc; }
  void eval(double r2, double& energy, double& f_over_r) const {
    const double r = std::sqrt(r2);
    const double dexp = std::exp(-alpha * (r - r0));
    energy = d0 * (dexp * dexp - dexp - dexp) - offset;
    f_over_r = 2.0 * alpha * d0 * (dexp * dexp - dexp) / r;
  }
  // Sets offset from the parameters (call after changing them).
  void update_offset() {
    const double dexp = std::exp(-alpha * (rc - r0));
    offset = shift ? d0 * (dexp * dexp - dexp - dexp) : 0.0;
  }
  std::string describe() const;
  static MorsePotential read(Table& s);
};

}  // namespace mpmx::dpd
