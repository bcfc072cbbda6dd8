// ctest-label: crosscheck
// M2: the same configurations through mpmx and LAMMPS (`lmp`, same potential files):
// total energy, per-atom forces and the virial pressure tensor agree to 1e-10 relative;
// a 100-step NVE trajectory agrees to 1e-8. LAMMPS's velocity Verlet and mpmx's
// leapfrog started with eq. 5.4 from the same on-step velocities give the same
// positions (the half-step velocity of leapfrog is Verlet's mid-step velocity).
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
#include "mpmx/md/system.hpp"
#include "mpmx/md/thermal.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/rng.hpp"

#include "mpmx/app/md/lammps_bar.hpp"

#include "../md/md_test_util.hpp"

using namespace mpmx::md;
namespace fs = std::filesystem;

namespace {

using mpmx::test::have_lmp;
using mpmx::test::kLammpsPotentials;

struct Case {
  std::string name;
  int cells;
  double a;
  std::string style;  // LAMMPS pair style
  std::string file;
  std::vector<std::string> elements;
  double tilt;          // shear the box (triclinic images) by this fraction
  int every_other = 0;  // every n-th atom is type 2
};

struct LammpsResult {
  double pe0 = 0, pe1 = 0, ke1 = 0;
  std::array<double, 6> p0{};  // virial pressure (bar): xx yy zz xy xz yz
  std::map<long, std::array<double, 3>> f0, x1, v1;
};

LammpsResult run_lammps(const Case& cs, const System& sys, const fs::path& dir, int steps, double dt) {
  fs::create_directories(dir);
  mpmx::app::md::write_lammps_data(sys, (dir / "data.lmp").string(), "crosscheck");
  {
    std::ofstream in(dir / "in.lmp");
    in << "units metal\natom_style atomic\nboundary p p p\natom_modify map array\n";
    in << "read_data data.lmp\n";
    in << fmt::format("pair_style {}\npair_coeff {} {}{}", cs.style, cs.style == "eam" ? "1 1" : "* *",
                      kLammpsPotentials, cs.file);
    for (const auto& e : cs.elements) in << " " << e;
    in << "\nneighbor 1.0 bin\nneigh_modify every 1 delay 0 check yes\n";
    in << "compute vir all pressure NULL virial\n";
    in << "thermo_style custom step pe ke c_vir[1] c_vir[2] c_vir[3] c_vir[4] c_vir[5] c_vir[6]\n";
    in << "thermo_modify format float %20.15g norm no\n";
    in << "run 0\n";
    in << "print \"R0 $(pe:%.17g) $(c_vir[1]:%.17g) $(c_vir[2]:%.17g) $(c_vir[3]:%.17g) "
          "$(c_vir[4]:%.17g) $(c_vir[5]:%.17g) $(c_vir[6]:%.17g)\"\n";
    in << "write_dump all custom f0.dump id fx fy fz modify sort id format float %.17g\n";
    in << fmt::format("timestep {:.17g}\nfix 1 all nve\nthermo {}\nrun {}\n", dt, steps, steps);
    in << "print \"R1 $(pe:%.17g) $(ke:%.17g)\"\n";
    in << "write_dump all custom x1.dump id xu yu zu modify sort id format float %.17g\n";
    in << "write_dump all custom v1.dump id vx vy vz modify sort id format float %.17g\n";
  }
  const std::string cmd = fmt::format(
      "cd '{}' && OMP_NUM_THREADS=1 lmp -in in.lmp -log log.lammps -screen none > /dev/null 2>&1", dir.string());
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("lmp failed in " + dir.string());
  LammpsResult r;
  std::ifstream log(dir / "log.lammps");
  std::string line;
  while (std::getline(log, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "R0") {
      s >> r.pe0;
      for (auto& p : r.p0) s >> p;
    } else if (tag == "R1") {
      s >> r.pe1 >> r.ke1;
    }
  }
  r.f0 = mpmx::test::read_lammps_dump(dir / "f0.dump");
  r.x1 = mpmx::test::read_lammps_dump(dir / "x1.dump");
  r.v1 = mpmx::test::read_lammps_dump(dir / "v1.dump");
  return r;
}

System make_system(const Case& cs, std::uint64_t seed) {
  EamSpec spec;
  spec.file = kLammpsPotentials + cs.file;
  spec.elements = cs.elements;
  Potential pot(spec);
  Crystal c = fcc(cs.cells, cs.cells, cs.cells, cs.a);
  RngStream r(seed, 1);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    c.atoms.x[i] += 0.15 * (2 * r.uniform() - 1);
    c.atoms.y[i] += 0.15 * (2 * r.uniform() - 1);
    c.atoms.z[i] += 0.15 * (2 * r.uniform() - 1);
    if (cs.every_other && i % cs.every_other == 0) c.atoms.type[i] = 1;
  }
  if (cs.tilt != 0) {
    // Shear the crystal with its images: x += t (y + z), y += t z (upper triangular).
    for (std::size_t i = 0; i < c.atoms.size(); ++i) {
      c.atoms.x[i] += cs.tilt * (c.atoms.y[i] + c.atoms.z[i]);
      c.atoms.y[i] += cs.tilt * c.atoms.z[i];
    }
    c.box.xy = cs.tilt * c.box.ly;
    c.box.xz = cs.tilt * c.box.lz;
    c.box.yz = cs.tilt * c.box.lz;
  }
  SystemOptions o;
  System s(c, pot, o);
  maxwell_velocities(s.edit_atoms(), s.type_mass(), 600.0, r);
  s.refresh();  // wraps the sheared atoms into the fundamental box
  return s;
}

double max_abs(const std::map<long, std::array<double, 3>>& m) {
  double v = 0;
  for (const auto& [id, a] : m)
    for (double c : a) v = std::max(v, std::abs(c));
  return v;
}

void crosscheck(const Case& cs) {
  if (!have_lmp()) GTEST_SKIP() << "lmp not installed";
  const double dt = 0.001;
  const int steps = 100;
  System sys = make_system(cs, 42 + cs.cells);
  const auto dir = fs::temp_directory_path() / ("mpmx_m2_" + cs.name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  const LammpsResult L = run_lammps(cs, sys, dir, steps, dt);
  const std::size_t n = sys.atoms().size();
  ASSERT_EQ(L.f0.size(), n);

  // Static: energy, forces, virial pressure.
  const double e_rel = std::abs(sys.potential_energy() - L.pe0) / std::abs(L.pe0);
  std::map<long, std::array<double, 3>> f;
  for (std::size_t i = 0; i < n; ++i) f[sys.atoms().id[i]] = {sys.atoms().fx[i], sys.atoms().fy[i], sys.atoms().fz[i]};
  double fdiff = 0;
  for (const auto& [id, lf] : L.f0)
    for (int c = 0; c < 3; ++c) fdiff = std::max(fdiff, std::abs(f[id][c] - lf[c]));
  const double f_rel = fdiff / max_abs(L.f0);
  // LAMMPS's virial pressure = W/V in bar; mpmx's Cauchy potential stress = -W/V.
  const double V = sys.box().volume();
  double pmax = 0, pdiff = 0;
  for (int c = 0; c < 6; ++c) {
    const double mine = sys.virial()[c] / V * mpmx::units::lammps_nktv2p;
    pmax = std::max(pmax, std::abs(L.p0[c]));
    pdiff = std::max(pdiff, std::abs(mine - L.p0[c]));
  }
  const double p_rel = pdiff / pmax;
  // The same through the stress API: sigma = -P (kinetic part about the mean removed
  // from both: compare the potential part only via virial()).
  std::printf("M2 %s: %zu atoms, energy rel %.3g, forces rel %.3g, pressure rel %.3g\n", cs.name.c_str(), n,
              e_rel, f_rel, p_rel);
  EXPECT_LT(e_rel, 1e-10);
  EXPECT_LT(f_rel, 1e-10);
  EXPECT_LT(p_rel, 1e-10);

  // Dynamics: 100 NVE steps from the same on-step velocities.
  sys.advance(steps, dt);
  double xdiff = 0, vdiff = 0;
  const Box& b = sys.box();
  for (std::size_t i = 0; i < n; ++i) {
    const auto& lx = L.x1.at(sys.atoms().id[i]);
    const auto& lv = L.v1.at(sys.atoms().id[i]);
    double d[3] = {sys.atoms().x[i] - lx[0], sys.atoms().y[i] - lx[1], sys.atoms().z[i] - lx[2]};
    // Remove whole lattice vectors (mpmx wraps at rebuilds, LAMMPS's xu is unwrapped).
    const double k3 = std::round(d[2] / b.lz);
    d[0] -= k3 * b.xz, d[1] -= k3 * b.yz, d[2] -= k3 * b.lz;
    const double k2 = std::round(d[1] / b.ly);
    d[0] -= k2 * b.xy, d[1] -= k2 * b.ly;
    d[0] -= std::round(d[0] / b.lx) * b.lx;
    for (int c = 0; c < 3; ++c) xdiff = std::max(xdiff, std::abs(d[c]));
    vdiff = std::max(vdiff, std::abs(sys.atoms().vx[i] - lv[0]));
    vdiff = std::max(vdiff, std::abs(sys.atoms().vy[i] - lv[1]));
    vdiff = std::max(vdiff, std::abs(sys.atoms().vz[i] - lv[2]));
  }
  const double v_rel = vdiff / max_abs(L.v1);
  const double pe_rel = std::abs(sys.potential_energy() - L.pe1) / std::abs(L.pe1);
  const double ke_rel = std::abs(sys.kinetic_energy() - L.ke1) / std::abs(L.ke1);
  std::printf("M2 %s: after %d steps: max |dx| %.3g A, velocity rel %.3g, pe rel %.3g, ke rel %.3g\n",
              cs.name.c_str(), steps, xdiff, v_rel, pe_rel, ke_rel);
  EXPECT_LT(xdiff, 1e-8);
  EXPECT_LT(v_rel, 1e-8);
  EXPECT_LT(pe_rel, 1e-8);
  EXPECT_LT(ke_rel, 1e-8);
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);  // keep it for a failure's post-mortem
}

}  // namespace

TEST(M2, Setfl500) { crosscheck({"setfl500", 5, 3.615, "eam/alloy", "Cu_mishin1.eam.alloy", {"Cu"}, 0.0}); }
TEST(M2, Setfl4000) { crosscheck({"setfl4000", 10, 3.615, "eam/alloy", "Cu_mishin1.eam.alloy", {"Cu"}, 0.0}); }
TEST(M2, SetflSheared500) {
  crosscheck({"sheared500", 5, 3.615, "eam/alloy", "Cu_mishin1.eam.alloy", {"Cu"}, 0.12});
}
TEST(M2, Funcfl500) { crosscheck({"funcfl500", 5, 3.615, "eam", "Cu_u3.eam", {}, 0.0}); }
TEST(M2, FinnisSinclairCuZr500) {
  crosscheck({"fs500", 5, 3.75, "eam/fs", "CuZr_mm.eam.fs", {"Cu", "Zr"}, 0.05, 4});
}
