#pragma once
// Readers for the EAM potential files users already have, turned into the tabulated
// form LAMMPS interpolates (pair_eam's file2array): F(rho) on a rho grid, rho(r) and
// z2r(r) = r*phi(r) on an r grid, all 1-based arrays (index 0 unused).
//   funcfl (.eam, DYNAMO single element): Z(r) given, z2r = 27.2*0.529 Z_i Z_j.
//   setfl  (.eam.alloy): one rho(r) per element, r*phi for each pair i >= j.
//   fs     (.eam.fs, Finnis-Sinclair): rho_ij(r) for every ordered element pair.
// A malformed or truncated file throws InputError naming file, line and what was expected.
#include <string>
#include <vector>

namespace mpmx::md {

// An element's crystal as its file's element line names it ("Z mass a lattice"; LAMMPS
// reads neither): empty where the line stops at the mass or the words are no lattice.
struct DeclaredLattice {
  std::string name;   // lower case as written: "fcc", "bcc", "hcp", or another word
  double constant = 0;  // Angstrom
};

struct EamTables {
  std::string file;
  std::string format;                 // "funcfl", "setfl", "fs"
  std::vector<std::string> elements;  // elements of the file
  std::vector<double> masses;         // amu, per file element
  std::vector<DeclaredLattice> lattices;  // per file element
  int atomic_number = 0;              // funcfl: line 2's (the file names no element)
  int nrho = 0, nr = 0;
  double drho = 0, dr = 0, rhomax = 0, cut = 0;
  std::vector<std::vector<double>> frho, rhor, z2r;  // 1-based
  // For type t mapped to file element e = map[t]:
  //   frho index e; rhor index of density that j contributes at i: rhor_index(e_j, e_i)
  //   is stored as type2rhor[e_j * n + e_i] like LAMMPS's type2rhor[jtype][itype].
  std::vector<int> rhor_index;  // n*n, n = elements.size()
  std::vector<int> z2r_index;   // n*n, symmetric

  int element_index(const std::string& name) const;  // -1 if absent
};

enum class EamFormat { funcfl, setfl, fs };

// Format from the file name: *.eam.alloy -> setfl, *.eam.fs -> fs, *.eam -> funcfl.
EamFormat eam_format_from_name(const std::string& path);
EamTables read_eam(const std::string& path, EamFormat format);
EamTables read_eam(const std::string& path);

// Finds a potential file: an absolute path as given; a relative one against `deck_dir`
// (the working directory when empty), then in /usr/share/lammps/potentials. Throws InputError listing the places tried.
std::string resolve_potential_file(const std::string& name, const std::string& deck_dir);

}  // namespace mpmx::md
