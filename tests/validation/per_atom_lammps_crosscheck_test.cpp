// ctest-label: crosscheck
// Per-atom output against LAMMPS (`lmp`) on the same atoms (issue 47): each atom's
// potential energy (compute pe/atom) and stress (compute stress/atom, pressure times
// volume, over the mean atomic volume) to round-off, and its structure label against
// compute cna/atom (the conventional CNA at LAMMPS's recommended cut-off for fcc,
// (1 + sqrt(1/2)) / 2 a) on a hot, sheared crystal with vacancies: the two analyses
// differ only in how the cut-off is set, so on a crystal whose shells stay apart they
// label every atom alike.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"
#include "mpmx/md/structure.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/md/thermal.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/rng.hpp"

#include "mpmx/app/md/lammps_bar.hpp"

#include "../md/md_test_util.hpp"

using namespace mpmx::md;
namespace fs = std::filesystem;

namespace {

struct Theirs {
  double pe = 0;
  std::array<double, 6> s{};
  int cna = 0;
};

// A 5 x 5 x 5 copper crystal at 600 K, jiggled by up to 0.1 A, sheared by 5% (xy) and
// with every 61st atom taken out.
System hot_sheared_copper() {
  Crystal c = fcc(5, 5, 5, 3.615);
  RngStream r(11, 1);
  Atoms kept;
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    if (i % 61 == 7) continue;
    const double x = c.atoms.x[i] + 0.1 * (2 * r.uniform() - 1), y = c.atoms.y[i] + 0.1 * (2 * r.uniform() - 1);
    const double z = c.atoms.z[i] + 0.1 * (2 * r.uniform() - 1);
    kept.push_back(x + 0.05 * y, y, z, 0, c.atoms.id[i]);
  }
  c.atoms = kept;
  c.box.xy = 0.05 * c.box.ly;
  SystemOptions o;
  o.per_atom = true;
  System s(c, mpmx::test::copper(), o);
  maxwell_velocities(s.edit_atoms(), s.type_mass(), 600.0, r);
  s.refresh();
  return s;
}

std::map<long, Theirs> run_lammps(const System& sys, const fs::path& dir) {
  fs::create_directories(dir);
  mpmx::app::md::write_lammps_data(sys, (dir / "data.lmp").string(), "crosscheck");
  {
    std::ofstream in(dir / "in.lmp");
    in << "units metal\natom_style atomic\nboundary p p p\natom_modify map array\nread_data data.lmp\n";
    in << "pair_style eam/alloy\npair_coeff * * " << mpmx::test::kCuMishin << " Cu\n";
    in << "compute pe all pe/atom\ncompute s all stress/atom NULL\n";
    in << fmt::format("compute cna all cna/atom {:.17g}\n", (1 + std::sqrt(0.5)) / 2 * 3.615);
    in << "dump d all custom 1 pa.dump id c_pe c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_cna\n";
    in << "dump_modify d sort id format float %.17g\nrun 0\n";
  }
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.lmp -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("lmp failed in " + dir.string());
  std::ifstream d(dir / "pa.dump");
  std::string line;
  while (std::getline(d, line) && line.rfind("ITEM: ATOMS", 0) != 0) {
  }
  std::map<long, Theirs> out;
  long id;
  Theirs t;
  double cna;
  while (d >> id >> t.pe >> t.s[0] >> t.s[1] >> t.s[2] >> t.s[3] >> t.s[4] >> t.s[5] >> cna) {
    t.cna = static_cast<int>(cna);
    out[id] = t;
  }
  return out;
}

}  // namespace

TEST(PerAtomLammps, EnergyStressAndStructureAgree) {
  if (!mpmx::test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  const System sys = hot_sheared_copper();
  const auto dir = fs::temp_directory_path() / ("mpmx_per_atom_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const auto L = run_lammps(sys, dir);
  const Atoms& at = sys.atoms();
  const std::size_t n = at.size();
  ASSERT_EQ(L.size(), n);
  const auto stress = sys.atom_stress_gpa();
  const auto labels = adaptive_cna(sys.snapshot(), sys.box(), sys.potential().cutoff());
  // LAMMPS's per-atom stress is pressure times volume (bar A^3, by its own eV A^-3 to bar
  // factor, rounded to 8 digits): sigma = S / (V / N), in eV A^-3 by that factor.
  const double per_atom_volume = sys.box().volume() / static_cast<double>(n);
  double de = 0, emax = 0, ds = 0, smax = 0;
  int same = 0, fcc_atoms = 0;
  std::map<int, int> lammps_labels;
  for (std::size_t i = 0; i < n; ++i) {
    const Theirs& t = L.at(static_cast<long>(at.id[i]));
    de = std::max(de, std::abs(sys.per_atom_energy()[i] - t.pe));
    emax = std::max(emax, std::abs(t.pe));
    for (int c = 0; c < 6; ++c) {
      const double theirs = t.s[c] / mpmx::units::lammps_nktv2p * mpmx::units::eV_per_A3_in_GPa / per_atom_volume;
      ds = std::max(ds, std::abs(stress[6 * i + c] - theirs));
      smax = std::max(smax, std::abs(theirs));
    }
    const int mine = static_cast<int>(labels[i]), theirs = t.cna == 5 ? 0 : t.cna;  // LAMMPS: 5 unknown
    same += mine == theirs;
    fcc_atoms += mine == 1;
    ++lammps_labels[t.cna];
  }
  std::printf("per-atom vs LAMMPS: %zu atoms, energy %.3g eV (max %.3g), stress %.3g GPa (max %.3g), "
              "structure %d of %zu alike (%d fcc; LAMMPS: %d fcc, %d unknown)\n",
              n, de, emax, ds, smax, same, n, fcc_atoms, lammps_labels[1], lammps_labels[5]);
  EXPECT_LT(de / emax, 1e-12);
  EXPECT_LT(ds / smax, 1e-10);
  EXPECT_EQ(same, static_cast<int>(n));
  EXPECT_GT(fcc_atoms, 0);
  EXPECT_LT(fcc_atoms, static_cast<int>(n));  // the vacancies' neighbours are not fcc
  fs::remove_all(dir);
}
