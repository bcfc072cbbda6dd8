#pragma once
// Tabulated EAM as LAMMPS evaluates it (pair_eam.cpp): every table turned into cubic
// pieces with 7 coefficients per knot (value, and derivative coefficients scaled by
// the grid spacing), looked up with p = r/dr + 1, m = int(p), clamped at the table
// ends; F(rho) is continued linearly beyond the last rho knot.
//
// EamSpec is the potential registry's entry "eam" (registry.hpp): a file in a format
// users already have (eam_file.hpp) and the file element of each atom type.
#include <string>
#include <string_view>
#include <vector>

#include "mpmx/core/table.hpp"
#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/potential/eam_file.hpp"

namespace mpmx::md {

class Eam {
 public:
  // `type_elements[t]` names the file element of atom type t (empty: all file elements
  // in file order; funcfl files have one).
  Eam(const EamTables& tables, const std::vector<std::string>& type_elements);

  double cutoff() const { return cut_; }
  int types() const { return static_cast<int>(map_.size()); }
  const std::vector<double>& masses() const { return masses_; }
  const std::vector<std::string>& type_names() const { return names_; }
  const std::string& file() const { return file_; }
  // What the file's element line says of each type's crystal (eam_file.hpp).
  const std::vector<DeclaredLattice>& declared_lattices() const { return lattices_; }

  ForceSums compute(const Neighbors& nb, ForceWork& w) const;        // double
  ForceSums compute_mixed(const Neighbors& nb, ForceWork& w) const;  // float pairs

  // Energy of an isolated pair/density evaluation, for tests.
  double pair_energy(double r, int ti, int tj) const;

  template <class Real>
  struct Tables;  // the kernel's view (defined in eam.cpp)

 private:
  std::string file_;
  std::vector<int> map_;  // type -> file element
  std::vector<double> masses_;
  std::vector<std::string> names_;
  std::vector<DeclaredLattice> lattices_;
  int nrho_ = 0, nr_ = 0, ntypes_ = 0;
  double rdr_ = 0, rdrho_ = 0, rhomax_ = 0, cut_ = 0;
  // Splines flattened: [function][knot 0..n][7].
  std::vector<double> frho_, rhor_, z2r_;
  std::vector<float> rhor_f_, z2r_f_;
  // Per type pair (ti * ntypes + tj): spline offsets (in doubles) of the density that
  // j gives i, and of z2r; per type: F offset.
  std::vector<int> rho_off_, z2r_off_, frho_off_;
  // One-type fast path (eam_one_type.hpp): per knot, the density-pass record (rho
  // c3..c6) and the force-pass record (rho c0..c2, z2r c0..c6).
  std::vector<double> rho1_, pair1_;
  std::vector<float> rho1f_, pair1f_;
};

// [potential] style = "eam": file (resolved against the deck's folder, then the LAMMPS
// potentials folder) and elements.
struct EamSpec {
  static constexpr std::string_view name = "eam";
  using Kernel = Eam;

  std::string file;                   // the potential file (format from its name); empty: not found
  std::vector<std::string> elements;  // the file element of each atom type

  // Parses the file now, so that `check` refuses what `run` would: a corrupt or truncated
  // file, an element it does not hold.
  static EamSpec read(Table& t, const std::string& deck_dir);
  // False when the file was not found (read said why).
  bool complete() const { return !file.empty(); }
  Eam make() const;
  // pair_style eam, eam/alloy or eam/fs and its pair_coeff lines for the potential made.
  std::string lammps_pair_lines(const Eam& made) const;
};

// LAMMPS's interpolate(): 7 coefficients per knot for values f[1..n] on spacing delta.
void eam_spline(int n, double delta, const std::vector<double>& f, double* out);

}  // namespace mpmx::md
