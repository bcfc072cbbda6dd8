#pragma once
// Sutton-Chen many-body potential (an analytic EAM):
//   E = eps [ 1/2 sum_ij (a/r_ij)^n - c sum_i sqrt(rho_i) ],  rho_i = sum_j (a/r_ij)^m
// truncated at a cutoff. One type. SuttonChenSpec is the potential registry's entry
// "sutton_chen" (registry.hpp).
#include <string>
#include <string_view>

#include "mpmx/core/table.hpp"
#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"

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

// [potential] style = "sutton_chen": epsilon (eV), a (Angstrom), c, n, m, cutoff
// (Angstrom), mass (amu).
struct SuttonChenSpec {
  static constexpr std::string_view name = "sutton_chen";
  using Kernel = SuttonChen;

  double epsilon = 0, a = 0, c = 0, cutoff = 0, mass = 0;
  int n = 0, m = 0;  // the exponents

  static SuttonChenSpec read(Table& t, const std::string& deck_dir);
  bool complete() const { return true; }
  SuttonChen make() const { return SuttonChen(epsilon, a, c, n, m, cutoff, mass); }
  // The LAMMPS route takes eam and lj only: throws InputError saying so.
  std::string lammps_pair_lines(const SuttonChen& made) const;
};

}  // namespace mpmx::md
