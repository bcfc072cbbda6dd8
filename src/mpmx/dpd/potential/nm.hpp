#pragma once
// The n-m pair potential (a minimum of depth e0 at r0, repulsive core r^-n, attraction
// r^-m; LAMMPS `pair_style nm/cut`), cut at rc and shifted to zero there:
//   U(r) = e0/(n - m) [m (r0/r)^n - n (r0/r)^m] - U_raw(rc),
//   F(r) = e0 n m/(n - m) [(r0/r)^n - (r0/r)^m] / r.
// Deck: style = "nm", e0 (eV), r0 (Angstrom), n, m (n > m > 0), cutoff, shift.
#include <cmath>
#include <string>
#include <string_view>

#include "mpmx/core/table.hpp"

namespace mpmx::dpd {

struct NmPotential {
  static constexpr std::string_view name = "nm";
  double e0 = 0, r0 = 1, n = 12, m = 6, rc = 1;
  bool shift = true;
  double offset = 0;

  double cutoff() const { return rc; }
  void eval(double r2, double& energy, double& f_over_r) const {
    const double r = std::sqrt(r2);
    const double an = std::pow(r0 / r, n), am = std::pow(r0 / r, m);
    const double e0nm = e0 / (n - m);
    energy = e0nm * (m * an - n * am) - offset;
    f_over_r = e0nm * n * m * (an - am) / r2;
  }
  void update_offset() {
    const double an = std::pow(r0 / rc, n), am = std::pow(r0 / rc, m);
    offset = shift ? e0 / (n - m) * (m * an - n * am) : 0.0;
  }
  std::string describe() const;
  static NmPotential read(Table& s);
};

}  // namespace mpmx::dpd
