#include "mpmx/md/potential/eam.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/potential/eam_kernel.hpp"
#include "mpmx/md/potential/eam_one_type.hpp"
#include "mpmx/md/potential/element_numbers.hpp"

namespace mpmx::md {

namespace {

// A funcfl file names no element: line 2 gives its atomic number, which the deck's
// element symbol must have ("" when it does, or when the file gives none).
std::string funcfl_element_problem(const std::string& el, const EamTables& t) {
  const int z = atomic_number(el);
  if (z == 0)
    return fmt::format("'{}' is not an element symbol (as written: 'Cu', 'Ni', 'Al')", el);
  if (t.atomic_number > 0 && z != t.atomic_number)
    return fmt::format("element '{}' (atomic number {}) is not that of {}, whose line 2 gives atomic number {} ({})",
                       el, z, t.file, t.atomic_number, element_symbol(t.atomic_number));
  return {};
}

}  // namespace

void eam_spline(int n, double delta, const std::vector<double>& f, double* out) {
  auto s = [out](int m, int c) -> double& { return out[7 * m + c]; };
  for (int m = 1; m <= n; ++m) s(m, 6) = f[m];
  s(1, 5) = s(2, 6) - s(1, 6);
  s(2, 5) = 0.5 * (s(3, 6) - s(1, 6));
  s(n - 1, 5) = 0.5 * (s(n, 6) - s(n - 2, 6));
  s(n, 5) = s(n, 6) - s(n - 1, 6);
  for (int m = 3; m <= n - 2; ++m)
    s(m, 5) = ((s(m - 2, 6) - s(m + 2, 6)) + 8.0 * (s(m + 1, 6) - s(m - 1, 6))) / 12.0;
  for (int m = 1; m <= n - 1; ++m) {
    s(m, 4) = 3.0 * (s(m + 1, 6) - s(m, 6)) - 2.0 * s(m, 5) - s(m + 1, 5);
    s(m, 3) = s(m, 5) + s(m + 1, 5) - 2.0 * (s(m + 1, 6) - s(m, 6));
  }
  s(n, 4) = 0.0;
  s(n, 3) = 0.0;
  for (int m = 1; m <= n; ++m) {
    s(m, 2) = s(m, 5) / delta;
    s(m, 1) = 2.0 * s(m, 4) / delta;
    s(m, 0) = 3.0 * s(m, 3) / delta;
  }
}

Eam::Eam(const EamTables& t, const std::vector<std::string>& type_elements) : file_(t.file) {
  const int ne = static_cast<int>(t.elements.size());
  if (type_elements.empty()) {
    for (int e = 0; e < ne; ++e) map_.push_back(e);
  } else {
    for (const auto& name : type_elements) {
      int e = t.element_index(name);
      if (t.format == "funcfl") e = 0;
      if (e < 0)
        throw InputError(fmt::format("{}: element '{}' is not in the file (it has: {})", t.file,
                                     name, fmt::join(t.elements, ", ")));
      map_.push_back(e);
    }
  }
  ntypes_ = static_cast<int>(map_.size());
  for (int e : map_) {
    masses_.push_back(t.masses[e]);
    lattices_.push_back(e < static_cast<int>(t.lattices.size()) ? t.lattices[e] : DeclaredLattice{});
    names_.push_back(t.format == "funcfl" && !type_elements.empty() ? type_elements[names_.size()]
                                                                    : t.elements[e]);
  }
  nrho_ = t.nrho;
  nr_ = t.nr;
  rdr_ = 1.0 / t.dr;
  rdrho_ = 1.0 / t.drho;
  rhomax_ = t.rhomax;
  cut_ = t.cut;

  const std::size_t fr = 7 * static_cast<std::size_t>(nrho_ + 1);
  const std::size_t rr = 7 * static_cast<std::size_t>(nr_ + 1);
  frho_.assign(fr * t.frho.size(), 0.0);
  for (std::size_t f = 0; f < t.frho.size(); ++f) eam_spline(nrho_, t.drho, t.frho[f], &frho_[f * fr]);
  rhor_.assign(rr * t.rhor.size(), 0.0);
  for (std::size_t f = 0; f < t.rhor.size(); ++f) eam_spline(nr_, t.dr, t.rhor[f], &rhor_[f * rr]);
  z2r_.assign(rr * t.z2r.size(), 0.0);
  for (std::size_t f = 0; f < t.z2r.size(); ++f) eam_spline(nr_, t.dr, t.z2r[f], &z2r_[f * rr]);
  rhor_f_.assign(rhor_.begin(), rhor_.end());
  z2r_f_.assign(z2r_.begin(), z2r_.end());

  if (ntypes_ == 1) {
    const int e = map_[0];
    const double* rh = &rhor_[t.rhor_index[e * ne + e] * rr];
    const double* z2 = &z2r_[t.z2r_index[e * ne + e] * rr];
    rho1_.assign(4 * static_cast<std::size_t>(nr_ + 1), 0.0);
    pair1_.assign(kEamPairStride * static_cast<std::size_t>(nr_ + 1), 0.0);
    for (int m = 0; m <= nr_; ++m) {
      for (int c = 0; c < 4; ++c) rho1_[4 * m + c] = rh[7 * m + 3 + c];
      for (int c = 0; c < 3; ++c) pair1_[kEamPairStride * m + c] = rh[7 * m + c];
      for (int c = 0; c < 7; ++c) pair1_[kEamPairStride * m + 3 + c] = z2[7 * m + c];
    }
    rho1f_.assign(rho1_.begin(), rho1_.end());
    pair1f_.assign(pair1_.begin(), pair1_.end());
  }
  rho_off_.resize(ntypes_ * ntypes_);
  z2r_off_.resize(ntypes_ * ntypes_);
  frho_off_.resize(ntypes_);
  for (int a = 0; a < ntypes_; ++a) {
    frho_off_[a] = static_cast<int>(map_[a] * fr);
    for (int b = 0; b < ntypes_; ++b) {
      // density at an atom of type a due to type b: LAMMPS type2rhor[b][a]
      rho_off_[a * ntypes_ + b] = static_cast<int>(t.rhor_index[map_[b] * ne + map_[a]] * rr);
      z2r_off_[a * ntypes_ + b] = static_cast<int>(t.z2r_index[map_[a] * ne + map_[b]] * rr);
    }
  }
}

template <class Real>
struct Eam::Tables {
  const Real* rhor;
  const Real* z2r;
  const double* frho;
  const int* rho_off;
  const int* z2r_off;
  const int* frho_off;
  int ntypes, nr, nrho;
  Real rdr;
  double rdrho, rhomax, cut;

  double cutsq() const { return cut * cut; }

  // p and knot m as pair_eam computes them.
  void locate(Real r, Real& p, int& m) const {
    p = r * rdr + Real(1);
    m = static_cast<int>(p);
    m = std::min(m, nr - 1);
    p -= static_cast<Real>(m);
    p = std::min(p, Real(1));
  }
  static Real value(const Real* c, Real p) { return ((c[3] * p + c[4]) * p + c[5]) * p + c[6]; }
  static Real slope(const Real* c, Real p) { return (c[0] * p + c[1]) * p + c[2]; }

  void density(Real r, int ti, int tj, Real& at_i, Real& at_j) const {
    Real p;
    int m;
    locate(r, p, m);
    at_i = value(rhor + rho_off[ti * ntypes + tj] + 7 * m, p);
    at_j = value(rhor + rho_off[tj * ntypes + ti] + 7 * m, p);
  }
  void embed(double rho, int t, double& F, double& Fp) const {
    double p = rho * rdrho + 1.0;
    int m = static_cast<int>(p);
    m = std::max(1, std::min(m, nrho - 1));
    p -= m;
    p = std::min(p, 1.0);
    const double* c = frho + frho_off[t] + 7 * m;
    Fp = (c[0] * p + c[1]) * p + c[2];
    F = ((c[3] * p + c[4]) * p + c[5]) * p + c[6];
    if (rho > rhomax) F += Fp * (rho - rhomax);
  }
  // phi and dE/dr of the pair, with the embedding terms F_i' rho_j' + F_j' rho_i'.
  void pair(Real r, int ti, int tj, Real fpi, Real fpj, Real& phi, Real& dedr) const {
    Real p;
    int m;
    locate(r, p, m);
    const Real rhoip = slope(rhor + rho_off[tj * ntypes + ti] + 7 * m, p);  // i's density at j
    const Real rhojp = slope(rhor + rho_off[ti * ntypes + tj] + 7 * m, p);  // j's density at i
    const Real* c = z2r + z2r_off[ti * ntypes + tj] + 7 * m;
    const Real z2p = slope(c, p);
    const Real z2 = value(c, p);
    const Real recip = Real(1) / r;
    phi = z2 * recip;
    const Real phip = z2p * recip - phi * recip;
    dedr = fpi * rhojp + fpj * rhoip + phip;
  }
};

ForceSums Eam::compute(const Neighbors& nb, ForceWork& w) const {
  if (ntypes_ == 1) {
    return eam_one_type(EamOneType<double>{rho1_.data(), pair1_.data(), frho_.data() + frho_off_[0], nr_, nrho_,
                                           rdr_, rdrho_, rhomax_, cut_},
                        nb, w);
  }
  const Tables<double> t{rhor_.data(), z2r_.data(), frho_.data(), rho_off_.data(), z2r_off_.data(),
                         frho_off_.data(), ntypes_, nr_, nrho_, rdr_, rdrho_, rhomax_, cut_};
  return eam_compute<double>(t, nb, w);
}

ForceSums Eam::compute_mixed(const Neighbors& nb, ForceWork& w) const {
  if (ntypes_ == 1) {
    return eam_one_type(EamOneType<float>{rho1f_.data(), pair1f_.data(), frho_.data() + frho_off_[0], nr_, nrho_,
                                          rdr_, rdrho_, rhomax_, cut_},
                        nb, w);
  }
  const Tables<float> t{rhor_f_.data(), z2r_f_.data(), frho_.data(), rho_off_.data(),
                        z2r_off_.data(), frho_off_.data(), ntypes_, nr_, nrho_,
                        static_cast<float>(rdr_), rdrho_, rhomax_, cut_};
  return eam_compute<float>(t, nb, w);
}

double Eam::pair_energy(double r, int ti, int tj) const {
  const Tables<double> t{rhor_.data(), z2r_.data(), frho_.data(), rho_off_.data(), z2r_off_.data(),
                         frho_off_.data(), ntypes_, nr_, nrho_, rdr_, rdrho_, rhomax_, cut_};
  double phi, dedr;
  t.pair(r, ti, tj, 0.0, 0.0, phi, dedr);
  return phi;
}

EamSpec EamSpec::read(Table& t, const std::string& deck_dir) {
  EamSpec spec;
  const std::string file = t.string("file");
  if (!file.empty()) {
    try {
      spec.file = resolve_potential_file(file, deck_dir);
    } catch (const InputError& e) {
      t.check(false, "file", e.what());
    }
  }
  spec.elements = t.strings("elements", {});
  if (!spec.file.empty()) {
    try {
      const EamTables tables = read_eam(spec.file);
      for (const auto& el : spec.elements)
        if (tables.format != "funcfl" && tables.element_index(el) < 0)
          t.check(false, "elements",
                  fmt::format("element '{}' is not in {} (it has: {})", el, spec.file,
                              fmt::join(tables.elements, ", ")));
        else if (tables.format == "funcfl")
          t.check(funcfl_element_problem(el, tables).empty(), "elements", funcfl_element_problem(el, tables));
    } catch (const InputError& e) {
      t.check(false, "file", e.what());
    }
  }
  return spec;
}

Eam EamSpec::make() const { return Eam(read_eam(file), elements); }

namespace {

// A path LAMMPS reads as one word: no blanks, quotes, '$' (variables) or '#' (comments).
std::string lammps_path(const std::string& file) {
  const std::string p = std::filesystem::absolute(file).lexically_normal().string();
  if (p.find_first_of(" \t\"'$#&") != std::string::npos)
    throw InputError(fmt::format("potential file '{}': LAMMPS input cannot name a path with blanks, quotes, "
                                 "'$', '#' or '&'; copy or link it elsewhere",
                                 p));
  return p;
}

}  // namespace

std::string EamSpec::lammps_pair_lines(const Eam& made) const {
  const std::string path = lammps_path(file);
  switch (eam_format_from_name(file)) {
    case EamFormat::funcfl: {  // one file per type, i i (LAMMPS mixes i j)
      std::string s = "pair_style eam\n";
      for (int t = 1; t <= made.types(); ++t) s += fmt::format("pair_coeff {} {} {}\n", t, t, path);
      return s;
    }
    case EamFormat::setfl:
      return fmt::format("pair_style eam/alloy\npair_coeff * * {} {}\n", path, fmt::join(made.type_names(), " "));
    case EamFormat::fs:
      return fmt::format("pair_style eam/fs\npair_coeff * * {} {}\n", path, fmt::join(made.type_names(), " "));
  }
  return {};  // every format is handled above
}

}  // namespace mpmx::md
