#pragma once
// Lennard-Jones 12-6 with a cutoff (optionally shifted to zero energy at the cutoff):
// phi(r) = 4 eps [(sigma/r)^12 - (sigma/r)^6], one type.
#include "mpmx/md/forces.hpp"
#include "mpmx/md/neighbor.hpp"

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

}  // namespace mpmx::md
