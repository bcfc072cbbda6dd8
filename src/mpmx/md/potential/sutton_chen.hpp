#pragma once
// Sutton-Chen many-body potential (an analytic EAM):
//   E = eps [ 1/2 sum_ij (a/r_ij)^n - c sum_i sqrt(rho_i) ],  rho_i = sum_j (a/r_ij)^m
// truncated at a cutoff. One type.
#include "mpmx/md/forces.hpp"
#include "mpmx/md/neighbor.hpp"

namespace mpmx::md {

class SuttonChen {
 public:
  SuttonChen(double epsilon, double a, double c, int n, int m, double cutoff, double mass);
  double cutoff() const { return cut_; }
  double mass() const { return mass_; }
  ForceSums compute(const Neighbors& nb, ForceWork& w) const;

  // Analytic pieces (eV, Angstrom).
  double cutsq() const { return cut_ * cut_; }
  void density(double r, int, int, double& at_i, double& at_j) const;
  void embed(double rho, int, double& F, double& Fp) const;
  void pair(double r, int, int, double fpi, double fpj, double& phi, double& dedr) const;

 private:
  double eps_, a_, c_;
  int n_, m_;
  double cut_, mass_;
};

}  // namespace mpmx::md
