#pragma once
// Lennard-Jones 12-6 with a cutoff (optionally shifted to zero energy at the cutoff):
// phi(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6], one type. LjSpec is the potential
// registry's entry "lj" (registry.hpp).
#include <string>
#include <string_view>

#include "mpmx/core/table.hpp"
#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

namespace mpmx::md {

class LennardJones {
 public:
  LennardJones(double epsilon, double sigma, double cutoff, double mass, bool shift = false);
  double cutoff() const { return cut_; }
  double mass() const { return mass_; }
  double phi(double r) const;    // eV (shifted if asked)
  double dphi(double r) const;   // eV/Angstrom
  ForceSums compute(const Neighbors& nb, ForceWork& w) const;

 private:
  double eps_, sigma_, cut_, mass_, shift_ = 0;
};

// [potential] style = "lj": epsilon (eV), sigma, cutoff (Angstrom), mass (amu), shift.
struct LjSpec {
  static constexpr std::string_view name = "lj";
  using Kernel = LennardJones;

  double epsilon = 0, sigma = 0, cutoff = 0, mass = 0;
  bool shift = false;  // energy shifted to zero at the cutoff

  static LjSpec read(Table& t, const std::string& deck_dir);
  bool complete() const { return true; }
  LennardJones make() const { return LennardJones(epsilon, sigma, cutoff, mass, shift); }
  // pair_style lj/cut, its pair_coeff (and pair_modify shift) lines.
  std::string lammps_pair_lines(const LennardJones& made) const;
};

}  // namespace mpmx::md
