#pragma once
// The standard DPD conservative force (Groot and Warren 1997; LAMMPS `pair dpd`'s A
// term): F(r) = a (1 - r/rc) along e_ij, U(r) = a rc/2 (1 - r/rc)^2, for r < rc.
// Deck: style = "dpd", a (eV/Angstrom), cutoff (Angstrom).
#include <cmath>
#include <string>
#include <string_view>

#include "mpmx/core/table.hpp"

namespace mpmx::dpd {

struct SoftPotential {
  static constexpr std::string_view name = "dpd";
  double a = 0;   // eV/Angstrom, force at contact
  double rc = 1;  // Angstrom

  double cutoff() const { return rc; }
  // For 0 < r^2 < rc^2: the pair energy (eV) and F/r (eV/Angstrom^2), F > 0 repulsive.
  void eval(double r2, double& energy, double& f_over_r) const {
    const double r = std::sqrt(r2);
    const double w = 1.0 - r / rc;
    energy = 0.5 * a * rc * w * w;
    f_over_r = a * w / r;
  }
  std::string describe() const;
  static SoftPotential read(Table& s);
};

}  // namespace mpmx::dpd
