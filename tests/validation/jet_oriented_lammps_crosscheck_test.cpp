// ctest-label: crosscheck
// Jets of oriented crystals (md/jet.hpp with [lattice] type and orient) through LAMMPS:
// bcc Fe with x along [111] at 0 K and fcc Cu with x along [110] at 10 K. The input the
// jet writer produces (lammps_jet.hpp), run by `lmp`, holds mpmx's atoms (count and
// positions), and its `lattice ... orient ...` line builds the crystal the sample was cut
// from (every atom of the jet on one of LAMMPS's sites, as many sites as the uncut
// block's tiles hold); a few steps' energies agree to round-off: positions to 1e-14 A,
// the energies to 2e-12 relative (measured 5e-13 to 9e-13, as for a jet of fcc along
// the cube axes, 8e-13: an offset already at step 0, the positions equal).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "mpmx/app/md/jet_run.hpp"
#include "mpmx/app/md/lammps_bar.hpp"
#include "mpmx/app/md/lammps_jet.hpp"
#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/jet.hpp"
#include "mpmx/particles/tile_planes.hpp"

#include "../md/md_test_util.hpp"

// A named namespace: the crosscheck program compiles its files in unity batches.
namespace jet_oriented {

using namespace mpmx::md;
using namespace mpmx::app::md;
namespace fs = std::filesystem;

using mpmx::particles::LatticeStyle;
using mpmx::particles::Orient;

struct Case {
  std::string name, file, element;
  LatticeStyle style;
  double a;
  Orient orient;
  std::array<int, 3> tiles;
  int piston;
  double notch_nm, temperature;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The rows of the thermo table in a LAMMPS log: step temp pe ke etotal press.
std::vector<std::vector<double>> thermo_rows(const fs::path& log) {
  std::ifstream in(log);
  std::vector<std::vector<double>> rows;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find("Step") != std::string::npos && line.find("TotEng") != std::string::npos) {
      inside = true;
      continue;
    }
    if (line.rfind("Loop time", 0) == 0) inside = false;
    if (!inside) continue;
    std::istringstream s(line);
    std::vector<double> v;
    double x;
    while (s >> x) v.push_back(x);
    if (v.size() == 6) rows.push_back(v);
  }
  return rows;
}

double periodic_distance(const std::array<double, 3>& p, const std::array<double, 3>& q,
                         const std::array<double, 3>& period) {
  double sq = 0;
  for (int k = 0; k < 3; ++k) {
    double d = p[k] - q[k];
    if (period[k] > 0) d -= period[k] * std::round(d / period[k]);
    sq += d * d;
  }
  return std::sqrt(sq);
}

void crosscheck(const Case& k) {
  if (!mpmx::test::have_lmp()) GTEST_SKIP() << "lmp (LAMMPS) not on PATH";
  EamSpec spec;
  spec.file = mpmx::test::kLammpsPotentials + k.file;
  spec.elements = {k.element};
  JetConfig c;
  c.scale = 1.0;
  c.cells = k.tiles;
  c.piston_cells = k.piston;
  c.notch_depth_nm = k.notch_nm;
  c.lattice_constant = k.a;
  c.lattice.style = k.style;
  c.lattice.orient = k.orient;
  c.temperature = k.temperature;
  c.seed = 3;
  const double dt = 0.001;
  const int steps = 40, every = 10;
  JetGeometry geo;
  System sys = build_jet(c, Potential(spec), {}, &geo);
  const BinGrid grid = jet_grid(geo, 8, 2);
  const auto dir = fs::temp_directory_path() / fmt::format("mpmx_jet_oriented_{}_{}", k.name, getpid());
  fs::remove_all(dir);
  write_lammps_jet(sys, geo, grid, spec, dt, steps, every, 0, dir.string());

  // The written input as it is, with full-precision thermo and the atoms dumped before
  // and after the run.
  std::string in = read_text(dir / kLammpsJetInput);
  const std::string thermo = "thermo_modify norm no\n";
  ASSERT_NE(in.find(thermo), std::string::npos);
  in.replace(in.find(thermo), thermo.size(), "thermo_modify norm no format float %.17g\n");
  const std::string dump = "write_dump all custom {} id x y z modify sort id format float %.17g\n";
  const std::size_t run = in.rfind("run ");
  ASSERT_NE(run, std::string::npos);
  in.insert(run, fmt::format(fmt::runtime(dump), "start.dump"));
  in += fmt::format(fmt::runtime(dump), "end.dump");
  std::ofstream(dir / kLammpsJetInput) << in;
  const std::size_t at = in.find("\nlattice ") + 1;  // the line, its newline included
  ASSERT_GT(at, 0u) << "in.jet names no lattice";
  const std::string lattice_line = in.substr(at, in.find('\n', at) + 1 - at);

  std::vector<std::array<double, 3>> start(sys.atoms().size());
  for (std::size_t i = 0; i < sys.atoms().size(); ++i)
    start[sys.atoms().id[i] - 1] = {sys.atoms().x[i], sys.atoms().y[i], sys.atoms().z[i]};
  std::vector<double> energy{mpmx::test::total_energy(sys)}, pe{sys.potential_energy()};
  for (int s = 0; s < steps; s += every) {
    sys.advance(every, dt);
    energy.push_back(mpmx::test::total_energy(sys));
    pe.push_back(sys.potential_energy());
  }
  run_lammps(dir.string(), 1, kLammpsJetInput, kLammpsJetStress);

  // 1. The atoms: LAMMPS holds mpmx's, at mpmx's positions, before and after the steps.
  const std::array<double, 3> yz{0, sys.box().ly, sys.box().lz};
  const auto before = mpmx::test::read_lammps_dump(dir / "start.dump");
  ASSERT_EQ(before.size(), sys.atoms().size());
  double worst0 = 0;
  for (const auto& [id, p] : before) worst0 = std::max(worst0, periodic_distance(p, start[id - 1], yz));
  const auto after = mpmx::test::read_lammps_dump(dir / "end.dump");
  ASSERT_EQ(after.size(), sys.atoms().size());
  double worst1 = 0;
  for (std::size_t i = 0; i < sys.atoms().size(); ++i)
    worst1 = std::max(worst1, periodic_distance(after.at(sys.atoms().id[i]),
                                                {sys.atoms().x[i], sys.atoms().y[i], sys.atoms().z[i]}, yz));
  EXPECT_LT(worst0, 1e-12);
  EXPECT_LT(worst1, 1e-12);

  // 2. The energies at each record.
  const auto rows = thermo_rows(dir / kLammpsBarLog);
  ASSERT_EQ(rows.size(), energy.size());
  double de = 0, dpe = 0;
  for (std::size_t t = 0; t < rows.size(); ++t) {
    EXPECT_EQ(rows[t][0], static_cast<double>(t * every));
    de = std::max(de, std::abs(rows[t][4] - energy[t]) / std::abs(energy[t]));
    dpe = std::max(dpe, std::abs(rows[t][2] - pe[t]) / std::abs(pe[t]));
    std::printf("jet-lammps %s: step %g  pe %.17g (LAMMPS %.17g)  etotal %.17g (LAMMPS %.17g)\n", k.name.c_str(),
                rows[t][0], pe[t], rows[t][2], energy[t], rows[t][4]);
  }
  EXPECT_LT(de, 2e-12);
  EXPECT_LT(dpe, 2e-12);
  EXPECT_GT(std::abs(pe.back() - pe.front()), 1e-3) << "the steps changed nothing: no test of the forces";

  // 3. The input's `lattice` line builds the crystal the sample was cut from.
  const mpmx::particles::TilePlanes tp = mpmx::particles::tile_planes(geo.lattice);
  const std::array<double, 3> box{k.tiles[0] * tp.length[0], k.tiles[1] * tp.length[1], k.tiles[2] * tp.length[2]};
  fs::create_directories(dir / "lattice");
  std::ofstream(dir / "lattice" / "in.lattice") << fmt::format(
      "units metal\natom_style atomic\nboundary p p p\n{}region box block 0 {:.17g} 0 {:.17g} 0 {:.17g} units box\n"
      "create_box 1 box\ncreate_atoms 1 box\nmass 1 1.0\n"
      "write_dump all custom sites.dump id x y z modify sort id format float %.17g\n",
      lattice_line, box[0], box[1], box[2]);
  ASSERT_EQ(std::system(fmt::format("cd '{}' && lmp -in in.lattice -log log.lattice -screen none > /dev/null 2>&1",
                                    (dir / "lattice").string())
                            .c_str()),
            0);
  const auto sites = mpmx::test::read_lammps_dump(dir / "lattice" / "sites.dump");
  EXPECT_EQ(static_cast<std::int64_t>(sites.size()), tp.atoms * k.tiles[0] * k.tiles[1] * k.tiles[2]);
  double worst_site = 0;
  for (const auto& p : start) {
    const std::array<double, 3> q{p[0] - geo.origin[0], p[1] - geo.origin[1], p[2] - geo.origin[2]};
    double best = INFINITY;
    for (const auto& [id, s] : sites) best = std::min(best, periodic_distance(q, s, box));
    worst_site = std::max(worst_site, best);
  }
  EXPECT_LT(worst_site, 1e-9) << "an atom of the jet is not on a site of the input's lattice";
  std::printf("jet-lammps %s: %zu atoms (%zu sites uncut), positions within %.2g A at step 0 and %.2g A at step "
              "%d, energy rel %.2g, pe rel %.2g, lattice sites within %.2g A\n",
              k.name.c_str(), start.size(), sites.size(), worst0, worst1, steps, de, dpe, worst_site);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);  // kept for a failure's post-mortem
}

}  // namespace jet_oriented

// bcc Fe (Fe_mm.eam.fs), x [111], y [-110], z [-1-12]: tiles 2.47 x 4.04 x 6.99 A of 6 atoms.
TEST(JetOrientedLammps, BccIronAlong111ZeroKelvin) {
  jet_oriented::crosscheck({"Fe111", "Fe_mm.eam.fs", "Fe", mpmx::particles::LatticeStyle::bcc, 2.8553,
              {{{1, 1, 1}, {-1, 1, 0}, {-1, -1, 2}}}, {24, 6, 2}, 3, 0.5, 0.0});
}

// fcc Cu (Mishin), x [110], y [1-10], z [00-1] (right-handed): tiles 2.56 x 2.56 x 3.615 A
// of 2 atoms, started at 20 K.
TEST(JetOrientedLammps, FccCopperAlong110TenKelvin) {
  jet_oriented::crosscheck({"Cu110", "Cu_mishin1.eam.alloy", "Cu", mpmx::particles::LatticeStyle::fcc, 3.615,
              {{{1, 1, 0}, {1, -1, 0}, {0, 0, -1}}}, {24, 10, 3}, 3, 0.6, 10.0});
}
