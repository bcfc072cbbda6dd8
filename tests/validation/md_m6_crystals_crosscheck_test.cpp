// ctest-label: crosscheck
// M6: bcc Fe, bcc Ta, bcc W, hcp Mg, Zr and B2 NiAl (two elements of one setfl file on a
// lattice with a basis) in three orientations each, mpmx against LAMMPS
// (`lmp`, the same potential files). LAMMPS builds the crystal itself (`lattice STYLE a0
// orient x ... orient y ... orient z ...`, create_atoms in mpmx's periodic box): the same
// atoms as mpmx's builder, its energy per atom at mpmx's lattice constant, its own
// lattice constant (where its pressure vanishes, from its pressure there and its slope)
// and the box-frame C11, C12, C44 by the same central differences, all to round-off;
// then a perturbed box read from a data file: energy, forces and virial to 1e-10.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"
#include "mpmx/md/bar.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"
#include "mpmx/particles/rng.hpp"

#include "../md/md_test_util.hpp"

namespace m6 {

using namespace mpmx::md;
using mpmx::particles::LatticeSpec;
using mpmx::particles::LatticeStyle;
using mpmx::particles::Orient;
namespace fs = std::filesystem;

struct Metal {
  std::string name, style, file, element;
  LatticeStyle lattice;
  std::string element2 = "";  // b2: the body centres' element
  int types() const { return element2.empty() ? 1 : 2; }
  std::string elements() const { return element2.empty() ? element : element + " " + element2; }
};

const Metal kFe{"Fe", "eam/fs", "Fe_mm.eam.fs", "Fe", LatticeStyle::bcc};
const Metal kTa{"Ta", "eam/alloy", "CuTa.eam.alloy", "Ta", LatticeStyle::bcc};
const Metal kW{"W", "eam/alloy", "W_zhou.eam.alloy", "W", LatticeStyle::bcc};
const Metal kMg{"Mg", "eam/fs", "Mg_mm.eam.fs", "Mg", LatticeStyle::hcp};
const Metal kZr{"Zr", "eam/fs", "Zr_mm.eam.fs", "Zr", LatticeStyle::hcp};
const Metal kNiAl{"NiAl", "eam/alloy", "NiAlH_jea.eam.alloy", "Ni", LatticeStyle::b2, "Al"};

// x along [100], [110], [111] (cubic); along a1, [01-10] and c (hcp, LAMMPS's frame).
const Orient kX100 = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
const Orient kX110 = {{{1, 1, 0}, {-1, 1, 0}, {0, 0, 1}}};
const Orient kX111 = {{{1, 1, 1}, {-1, 1, 0}, {-1, -1, 2}}};
const Orient kXa2 = {{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}};
const Orient kXc = {{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};

Potential potential(const Metal& m) {
  EamSpec spec;
  spec.file = mpmx::test::kLammpsPotentials + m.file;
  spec.elements = {m.element};
  if (!m.element2.empty()) spec.elements.push_back(m.element2);
  return Potential(spec);
}

std::string orient_text(const Orient& o) {
  std::string s;
  for (int d = 0; d < 3; ++d) s += fmt::format(" orient {} {} {} {}", "xyz"[d], o[d][0], o[d][1], o[d][2]);
  return s;
}

// Runs `script` (after the units and the pair lines) in `dir`; the lines of its log that
// start with "R " as numbers.
std::vector<std::vector<double>> run_lammps(const Metal& m, const fs::path& dir, const std::string& setup,
                                            const std::string& script) {
  fs::create_directories(dir);
  {
    std::ofstream in(dir / "in.lmp");
    in << "units metal\natom_style atomic\nboundary p p p\natom_modify map array\n" << setup;
    in << fmt::format("pair_style {}\npair_coeff * * {}{} {}\n", m.style, mpmx::test::kLammpsPotentials, m.file,
                      m.elements());
    in << "neighbor 1.0 bin\ncompute vir all pressure NULL virial\n";
    in << "thermo_style custom step pe c_vir[1] c_vir[2] c_vir[3] c_vir[4] c_vir[5] c_vir[6]\n";
    in << script;
  }
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.lmp -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("lmp failed in " + dir.string());
  std::vector<std::vector<double>> rows;
  std::ifstream log(dir / "log.lammps");
  std::string line;
  while (std::getline(log, line)) {
    if (line.rfind("R ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    std::vector<double> v;
    double x;
    while (s >> x) v.push_back(x);
    rows.push_back(v);
  }
  return rows;
}

// A LAMMPS state line: run 0, then "R pe pxx pyy pzz pxy pxz pyz" (virial pressure, bar).
const char* kState = "run 0\nprint \"R $(pe:%.17g) $(c_vir[1]:%.17g) $(c_vir[2]:%.17g) $(c_vir[3]:%.17g) "
                     "$(c_vir[4]:%.17g) $(c_vir[5]:%.17g) $(c_vir[6]:%.17g)\"\n";

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

// The tiles of a box at least 10 A on every edge (and two lattice constants).
std::array<int, 3> box_tiles(const LatticeSpec& spec) {
  const auto tile = mpmx::particles::lattice_tile(spec);
  const auto least = equilibrium_tiles(spec);
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d) n[d] = std::max(least[d], static_cast<int>(std::ceil(10.0 / tile.length[d])));
  return n;
}

void crosscheck(const Metal& m, const Orient& orient, const std::string& label) {
  if (!mpmx::test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  const Potential pot = potential(m);
  LatticeSpec spec;
  spec.style = m.lattice;
  spec.orient = orient;
  const CrystalEquilibrium eq = lattice_equilibrium(pot, spec);
  spec.constant = eq.lattice_constant;
  const std::array<int, 3> tiles = box_tiles(spec);
  const Crystal c = mpmx::particles::oriented_crystal(spec, tiles);
  const Box& b = c.box;
  const auto dir = fs::temp_directory_path() / fmt::format("mpmx_m6_{}_{}_{}", m.name, label, getpid());
  fs::remove_all(dir);

  // 1. LAMMPS's own lattice in mpmx's box: atoms, energy, pressure, lattice constant, constants.
  const double e = 1e-5;
  // b2: LAMMPS's bcc with its second basis atom (the body centre) of type 2.
  const bool b2 = m.lattice == LatticeStyle::b2;
  std::string setup = fmt::format(
      "lattice {} {:.17g}{}\nregion box block 0 {:.17g} 0 {:.17g} 0 {:.17g} units box\ncreate_box {} box\n"
      "create_atoms 1 box{}\n",
      b2 ? "bcc" : mpmx::particles::lattice_name(m.lattice), spec.constant, orient_text(orient), b.lx, b.ly, b.lz,
      m.types(), b2 ? " basis 2 2" : "");
  for (int t = 0; t < m.types(); ++t) setup += fmt::format("mass {} {:.17g}\n", t + 1, pot.mass(t));
  std::string script = "print \"R $(atoms)\"\nwrite_dump all custom atoms.dump id x y z modify sort id format float "
                       "%.17g\n";
  script += kState;
  const std::string back = fmt::format("change_box all x final 0 {0:.17g} y final 0 {1:.17g} z final 0 {2:.17g} "
                                       "xy final 0 remap units box\n",
                                       b.lx, b.ly, b.lz);
  script += "change_box all triclinic\n";
  for (double s : {1 + e, 1 - e})  // isotropic: the pressure's slope in a
    script += fmt::format("change_box all x scale {0:.17g} y scale {0:.17g} z scale {0:.17g} remap\n{1}{2}", s,
                          kState, back);
  for (double s : {e, -e})  // uniaxial x: C11, C12
    script += fmt::format("change_box all x final 0 {:.17g} remap units box\n{}{}", b.lx * (1 + s), kState, back);
  for (double s : {e, -e})  // shear x += gamma y: C44
    script += fmt::format("change_box all xy final {:.17g} remap units box\n{}{}", s * b.ly, kState, back);
  const auto R = run_lammps(m, dir / "lattice", setup, script);
  ASSERT_EQ(R.size(), 8u) << "LAMMPS log in " << dir;
  ASSERT_EQ(static_cast<std::size_t>(R[0][0]), c.atoms.size()) << "LAMMPS's lattice holds another atom count";

  // The same sites: each LAMMPS atom on an mpmx atom (modulo the box).
  const auto L = mpmx::test::read_lammps_dump(dir / "lattice" / "atoms.dump");
  double worst_site = 0;
  for (const auto& [id, p] : L) {
    double best = INFINITY;
    for (std::size_t i = 0; i < c.atoms.size(); ++i) {
      double d[3] = {p[0] - c.atoms.x[i], p[1] - c.atoms.y[i], p[2] - c.atoms.z[i]};
      const double len[3] = {b.lx, b.ly, b.lz};
      double sq = 0;
      for (int k = 0; k < 3; ++k) {
        d[k] -= len[k] * std::round(d[k] / len[k]);
        sq += d[k] * d[k];
      }
      best = std::min(best, sq);
    }
    worst_site = std::max(worst_site, std::sqrt(best));
  }
  EXPECT_LT(worst_site, 1e-9) << "an atom of LAMMPS's lattice is not one of mpmx's";

  const double n = static_cast<double>(c.atoms.size());
  // LAMMPS's bar in GPa through its own eV/A^3 in bar (mpmx's GPa figure is CODATA 2018's).
  const double to_gpa = mpmx::units::eV_per_A3_in_GPa / mpmx::units::lammps_nktv2p;
  auto p_of = [](const std::vector<double>& r) { return (r[1] + r[2] + r[3]) / 3.0; };
  const double e_lmp = R[1][0] / n;
  const double p0 = p_of(R[1]) * to_gpa;
  const double dpda = (p_of(R[2]) - p_of(R[3])) * to_gpa / (2 * e * spec.constant);
  const double a_lmp = spec.constant - p0 / dpda;  // LAMMPS's zero of the pressure
  // sigma = -P: C11 = -dPxx/de, C12 = -dPyy/de, C44 = -dPxy/dgamma.
  const double c11 = -(R[4][1] - R[5][1]) * to_gpa / (2 * e);
  const double c12 = -(R[4][2] - R[5][2]) * to_gpa / (2 * e);
  const double c44 = -(R[6][4] - R[7][4]) * to_gpa / (2 * e);
  std::printf("M6 %s %s: %zu atoms, a0 %.12g A (LAMMPS %.12g, rel %.2g), E %.12g eV/atom (rel %.2g), p at a0 "
              "%.2g GPa; C11 %.8g (rel %.2g) C12 %.8g (rel %.2g) C44 %.8g (rel %.2g) GPa; sites within %.2g A\n",
              m.name.c_str(), label.c_str(), c.atoms.size(), eq.lattice_constant, a_lmp,
              rel(a_lmp, eq.lattice_constant), eq.energy_per_atom, rel(e_lmp, eq.energy_per_atom), p0, eq.c11_gpa,
              rel(c11, eq.c11_gpa), eq.c12_gpa, rel(c12, eq.c12_gpa), eq.c44_gpa, rel(c44, eq.c44_gpa), worst_site);
  EXPECT_LT(rel(a_lmp, eq.lattice_constant), 1e-12);
  EXPECT_LT(rel(e_lmp, eq.energy_per_atom), 1e-12);
  // A difference of stresses over 2e-5: round-off of the stress (1e-15 of its parts) over e.
  EXPECT_LT(std::abs(c11 - eq.c11_gpa), 1e-8 * std::abs(eq.c11_gpa) + 1e-6);
  EXPECT_LT(std::abs(c12 - eq.c12_gpa), 1e-8 * std::abs(eq.c11_gpa) + 1e-6);
  EXPECT_LT(std::abs(c44 - eq.c44_gpa), 1e-8 * std::abs(eq.c11_gpa) + 1e-6);

  // 2. A perturbed box through a data file: energy, forces, virial.
  Crystal moved = c;
  mpmx::particles::RngStream r(47, 6);
  for (std::size_t i = 0; i < moved.atoms.size(); ++i) {
    moved.atoms.x[i] += 0.1 * (2 * r.uniform() - 1);
    moved.atoms.y[i] += 0.1 * (2 * r.uniform() - 1);
    moved.atoms.z[i] += 0.1 * (2 * r.uniform() - 1);
  }
  const System sys(moved, pot);
  {
    fs::create_directories(dir / "perturbed");
    std::ofstream d(dir / "perturbed" / "data.lmp");
    d << "mpmx M6\n\n" << moved.atoms.size() << " atoms\n" << m.types() << " atom types\n\n";
    d << fmt::format("0 {:.17g} xlo xhi\n0 {:.17g} ylo yhi\n0 {:.17g} zlo zhi\n\nMasses\n\n", b.lx, b.ly, b.lz);
    for (int t = 0; t < m.types(); ++t) d << fmt::format("{} {:.17g}\n", t + 1, pot.mass(t));
    d << "\nAtoms # atomic\n\n";
    for (std::size_t i = 0; i < moved.atoms.size(); ++i)
      d << fmt::format("{} {} {:.17g} {:.17g} {:.17g}\n", moved.atoms.id[i], moved.atoms.type[i] + 1, moved.atoms.x[i],
                       moved.atoms.y[i], moved.atoms.z[i]);
  }
  const auto P = run_lammps(m, dir / "perturbed", "read_data data.lmp\n",
                            std::string(kState) +
                                "write_dump all custom f.dump id fx fy fz modify sort id format float %.17g\n");
  ASSERT_EQ(P.size(), 1u);
  const auto F = mpmx::test::read_lammps_dump(dir / "perturbed" / "f.dump");
  ASSERT_EQ(F.size(), moved.atoms.size());
  double fdiff = 0, fmax = 0;
  for (std::size_t i = 0; i < sys.atoms().size(); ++i) {
    const auto& lf = F.at(sys.atoms().id[i]);
    const double mine[3] = {sys.atoms().fx[i], sys.atoms().fy[i], sys.atoms().fz[i]};
    for (int k = 0; k < 3; ++k) fdiff = std::max(fdiff, std::abs(mine[k] - lf[k])), fmax = std::max(fmax, std::abs(lf[k]));
  }
  const double V = sys.box().volume();
  double pdiff = 0, pmax = 0;
  for (int k = 0; k < 6; ++k) {
    const double mine = sys.virial()[k] / V * mpmx::units::lammps_nktv2p;
    pdiff = std::max(pdiff, std::abs(mine - P[0][1 + k]));
    pmax = std::max(pmax, std::abs(P[0][1 + k]));
  }
  const double e_rel = rel(sys.potential_energy(), P[0][0]);
  std::printf("M6 %s %s perturbed: energy rel %.2g, forces rel %.2g, virial rel %.2g\n", m.name.c_str(),
              label.c_str(), e_rel, fdiff / fmax, pdiff / pmax);
  EXPECT_LT(e_rel, 1e-10);
  EXPECT_LT(fdiff / fmax, 1e-10);
  EXPECT_LT(pdiff / pmax, 1e-10);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);  // kept for a failure's post-mortem
}

}  // namespace m6

TEST(M6, FeBcc100) { m6::crosscheck(m6::kFe, m6::kX100, "x100"); }
TEST(M6, FeBcc110) { m6::crosscheck(m6::kFe, m6::kX110, "x110"); }
TEST(M6, FeBcc111) { m6::crosscheck(m6::kFe, m6::kX111, "x111"); }
TEST(M6, TaBcc100) { m6::crosscheck(m6::kTa, m6::kX100, "x100"); }
TEST(M6, TaBcc110) { m6::crosscheck(m6::kTa, m6::kX110, "x110"); }
TEST(M6, TaBcc111) { m6::crosscheck(m6::kTa, m6::kX111, "x111"); }
TEST(M6, WBcc100) { m6::crosscheck(m6::kW, m6::kX100, "x100"); }
TEST(M6, WBcc110) { m6::crosscheck(m6::kW, m6::kX110, "x110"); }
TEST(M6, WBcc111) { m6::crosscheck(m6::kW, m6::kX111, "x111"); }
TEST(M6, MgHcpXa1) { m6::crosscheck(m6::kMg, m6::kX100, "x_a1"); }
TEST(M6, MgHcpXa2) { m6::crosscheck(m6::kMg, m6::kXa2, "x_01-10"); }
TEST(M6, MgHcpXc) { m6::crosscheck(m6::kMg, m6::kXc, "x_c"); }
TEST(M6, ZrHcpXa1) { m6::crosscheck(m6::kZr, m6::kX100, "x_a1"); }
TEST(M6, ZrHcpXa2) { m6::crosscheck(m6::kZr, m6::kXa2, "x_01-10"); }
TEST(M6, ZrHcpXc) { m6::crosscheck(m6::kZr, m6::kXc, "x_c"); }
TEST(M6, NiAlB2100) { m6::crosscheck(m6::kNiAl, m6::kX100, "x100"); }
TEST(M6, NiAlB2110) { m6::crosscheck(m6::kNiAl, m6::kX110, "x110"); }
TEST(M6, NiAlB2111) { m6::crosscheck(m6::kNiAl, m6::kX111, "x111"); }

// The direct-MD bar of an oriented crystal (bcc Fe, x along [111]): its walls a hair
// outside its end planes, as fcc's, and at 0 K unstrained its inner slabs hold no stress.
TEST(M6, BarOfOrientedBccEndsOnItsPlanes) {
  using namespace mpmx::md;
  BarConfig c;
  c.lattice.style = mpmx::particles::LatticeStyle::bcc;
  c.lattice.orient = m6::kX111;
  c.lattice_constant = 2.855324860793;
  c.cells_x = 32;  // 79 A: slabs 2 to 5 lie two cutoffs (EAM's reach) from the ends
  c.cells_yz = 2;
  c.bins = 8;
  Bar bar(c, m6::potential(m6::kFe));
  const System& s = bar.system();
  const auto [lo, hi] = std::minmax_element(s.atoms().x.begin(), s.atoms().x.end());
  EXPECT_NEAR(*lo - s.walls().lo, 1e-6, 1e-9);
  EXPECT_NEAR(s.walls().hi - *hi, 1e-6, 1e-9);
  EXPECT_EQ(s.atoms().size(), 32u * 2 * 2 * 6);
  const auto st = bar.slab_stress_gpa();
  for (std::size_t b = 2; b + 2 < st.size(); ++b) EXPECT_LT(std::abs(st[b][0]), 1e-6) << "slab " << b;
}
