// ctest-label: crosscheck
// A dump frame's per-atom columns read back by LAMMPS as a user reads them (issue 53,
// item 1): hot fcc Cu, bcc Ta and hcp Mg boxes run long enough that the engine's spatial
// sort has put their atoms out of id order; `write_dump_frame` writes pe, stress and
// structure; LAMMPS reruns the file into an empty box with `add yes` (which numbers the
// atoms by row) and computes pe/atom, stress/atom and cna/atom. Each of our rows must
// then hold the numbers LAMMPS gives the atom of that row and of that id: rows by id, the
// columns on their own atoms. pe and stress agree to the dump's ten digits; the structure
// labels agree where LAMMPS's fixed-cut-off CNA and our adaptive one see the same
// neighbours (most atoms of a hot crystal; docs/md.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"
#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

#include "../md/md_test_util.hpp"

namespace dump_rerun {

using namespace mpmx;
namespace fs = std::filesystem;

struct Case {
  std::string name, file, element;
  particles::LatticeStyle style;
  double a, c_over_a;
  std::array<int, 3> tiles;
  double temperature;  // K; the atoms start at twice it
  double cna_cutoff;   // LAMMPS's recommended cna/atom cut-off for the lattice
};

struct Row {
  long id = 0;
  std::vector<double> v;
};

// The ATOMS rows of the last frame of a LAMMPS text dump, in file order, and the header's
// column names after "ITEM: ATOMS".
std::vector<Row> read_rows(const fs::path& path, std::vector<std::string>& columns) {
  std::ifstream in(path);
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("ITEM: ATOMS", 0) == 0) {
      rows.clear();
      columns.clear();
      std::istringstream h(line.substr(11));
      for (std::string c; h >> c;) columns.push_back(c);
      continue;
    }
    if (line.rfind("ITEM:", 0) == 0 || columns.empty()) continue;
    std::istringstream r(line);
    Row row;
    r >> row.id;
    for (double x; r >> x;) row.v.push_back(x);
    if (row.v.size() + 1 == columns.size()) rows.push_back(row);
  }
  return rows;
}

void check_case(const Case& k) {
  particles::LatticeSpec spec;
  spec.style = k.style;
  spec.constant = k.a;
  spec.c_over_a = k.c_over_a;
  md::EamSpec pot;
  pot.file = test::kLammpsPotentials + k.file;
  pot.elements = {k.element};
  md::SystemOptions o;
  o.per_atom = true;
  md::System sys(particles::oriented_crystal(spec, k.tiles), md::Potential(pot), o);
  sys.thermalize(k.temperature, 5, 0);
  sys.advance(300, 0.001);
  const auto& ids = sys.atoms().id;
  std::size_t out_of_place = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) out_of_place += ids[i] != static_cast<std::int64_t>(i + 1);
  ASSERT_GT(out_of_place, ids.size() / 2) << k.name << ": the box must be stored out of id order";

  const fs::path dir = test::scratch_root() / ("dump_rerun_" + k.name);
  fs::create_directories(dir);
  {
    std::ofstream d(dir / "frame.dump");
    md::write_dump_frame(d, sys, {"pe", "stress", "structure"});
  }
  {
    const auto& b = sys.box();
    std::ofstream in(dir / "in.lmp");
    in << "units metal\natom_style atomic\nboundary p p p\natom_modify map array\n";
    in << fmt::format("region r block 0 {:.17g} 0 {:.17g} 0 {:.17g}\ncreate_box 1 r\n", b.lx, b.ly, b.lz);
    in << fmt::format("mass 1 {:.17g}\n", sys.type_mass()[0]);
    in << fmt::format("pair_style {}\npair_coeff * * {} {}\n",
                      k.file.ends_with(".fs") ? "eam/fs" : "eam/alloy", pot.file, k.element);
    in << "compute pe all pe/atom\ncompute s all stress/atom NULL\n";
    in << fmt::format("compute cna all cna/atom {:.17g}\n", k.cna_cutoff);
    in << "dump d all custom 1 theirs.dump id c_pe c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_cna\n";
    in << "dump_modify d sort id format float %.17g\n";
    in << "rerun frame.dump dump x y z vx vy vz box yes add yes\n";
  }
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.lmp -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  ASSERT_EQ(std::system(cmd.c_str()), 0) << "lmp failed in " << dir;

  std::vector<std::string> mine_cols, their_cols;
  const auto mine = read_rows(dir / "frame.dump", mine_cols);
  const auto theirs = read_rows(dir / "theirs.dump", their_cols);
  ASSERT_EQ(mine.size(), ids.size());
  ASSERT_EQ(theirs.size(), ids.size());
  const auto col = [&](const char* name) {
    const auto it = std::find(mine_cols.begin(), mine_cols.end(), name);
    EXPECT_NE(it, mine_cols.end()) << name;
    return static_cast<std::size_t>(it - mine_cols.begin()) - 1;  // v holds the columns after id
  };
  const std::size_t pe = col("pe"), sxx = col("sxx"), label = col("structure");
  const double volume = sys.box().volume() / static_cast<double>(ids.size());
  double de = 0, ds = 0, smax = 0;
  std::size_t same_label = 0;
  for (std::size_t r = 0; r < mine.size(); ++r) {
    ASSERT_EQ(mine[r].id, static_cast<long>(r + 1)) << k.name << ": row " << r;  // rows by id
    ASSERT_EQ(theirs[r].id, static_cast<long>(r + 1));  // LAMMPS's number of the row
    de = std::max(de, std::abs(mine[r].v[pe] - theirs[r].v[0]));
    for (int c = 0; c < 6; ++c) {
      // LAMMPS: stress times volume in bar A^3 (compression positive in its pressure);
      // ours: GPa over V / N, tension positive, the same sign as its tensor.
      const double t = theirs[r].v[1 + c] / units::lammps_nktv2p * units::eV_per_A3_in_GPa / volume;
      ds = std::max(ds, std::abs(mine[r].v[sxx + c] - t));
      smax = std::max(smax, std::abs(t));
    }
    const int t_label = static_cast<int>(theirs[r].v[7]);
    same_label += static_cast<int>(mine[r].v[label]) == (t_label == 5 ? 0 : t_label);
  }
  const double agree = static_cast<double>(same_label) / static_cast<double>(mine.size());
  std::printf("%s at %g K: %zu atoms (%zu out of id order), pe within %.3g eV, stress within %.3g GPa (max %.3g), "
              "structure labels alike for %.1f%%\n",
              k.name.c_str(), k.temperature, ids.size(), out_of_place, de, ds, smax, 100 * agree);
  // Positions and columns carry ten digits: round-off of the file, not of either code.
  EXPECT_LT(de, 1e-6) << k.name;
  EXPECT_LT(ds, 1e-6 * smax) << k.name;
  EXPECT_GT(agree, 0.8) << k.name;
}

TEST(DumpRerunLammps, HotFccCuColumnsOnTheirAtoms) {
  if (!test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  check_case({"cu_fcc", "Cu_mishin1.eam.alloy", "Cu", particles::LatticeStyle::fcc, 3.615, 0, {5, 5, 5}, 700.0,
              (1 + std::sqrt(0.5)) / 2 * 3.615});
}

TEST(DumpRerunLammps, HotBccTaColumnsOnTheirAtoms) {
  if (!test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  check_case({"ta_bcc", "CuTa.eam.alloy", "Ta", particles::LatticeStyle::bcc, 3.3026, 0, {6, 6, 6}, 1000.0,
              (1 + std::sqrt(2.0)) / 2 * 3.3026});
}

TEST(DumpRerunLammps, HotHcpMgColumnsOnTheirAtoms) {
  if (!test::have_lmp()) GTEST_SKIP() << "lmp not installed";
  check_case({"mg_hcp", "Mg_mm.eam.fs", "Mg", particles::LatticeStyle::hcp, 3.19, 1.623, {6, 4, 4}, 300.0,
              (1 + std::sqrt(0.5)) / 2 * std::sqrt(2.0) * 3.19});
}

}  // namespace dump_rerun
