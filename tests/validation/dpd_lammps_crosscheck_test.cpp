// ctest-label: crosscheck
// The DPD engine against LAMMPS (Debian's lmp) on the same configurations (issue 16):
// the seedless quantities at step 0, the conservative energy, every particle's
// conservative force and the conservative virial (LAMMPS: compute pressure NULL virial),
// agree to 1e-10 relative, for the soft DPD force of the isothermal DPD fluid (LAMMPS
// pair python: Debian's build has no DPD-BASIC, so no pair dpd), the Morse Cu
// mesoparticle crystal (pair morse, shifted) including a box under twice the cutoff,
// and the n-m form (pair nm/cut). With gamma = 0 the DPD integrators reduce to
// velocity Verlet: 200 NVE steps agree with LAMMPS's fix nve to 1e-8.
// Skips with a message when lmp is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <unistd.h>

#include "../dpd/dpd_test_util.hpp"
#include "mpmx/app/dpd/lammps_deck.hpp"

namespace {

using namespace mpmx;
namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("mpmx_dpd_lammps_" + std::to_string(getpid())) / name;
  fs::create_directories(d);
  return d;
}

struct Cleanup {
  ~Cleanup() {
    std::error_code ec;
    fs::remove_all(fs::temp_directory_path() / ("mpmx_dpd_lammps_" + std::to_string(getpid())), ec);
  }
} cleanup;

// Step-0 comparison: energy, forces by id and (periodic boxes) the virial.
void compare_step0(const dpd::System& s, const std::string& name, bool compare_virial = true) {
  if (!app::dpd::lammps_available()) GTEST_SKIP() << "lmp (LAMMPS) is not installed: apt-get install lammps";
  const fs::path dir = scratch(name);
  app::dpd::write_lammps_dpd(s, {}, dir.string());
  const auto r = app::dpd::run_lammps_dpd(dir.string());
  const dpd::Particles& p = s.particles();
  ASSERT_EQ(r.id.size(), p.size());
  std::map<long, std::size_t> at;
  for (std::size_t i = 0; i < p.size(); ++i) at[p.id[i]] = i;
  double fmax = 0, dmax = 0;
  for (std::size_t k = 0; k < r.id.size(); ++k) {
    const std::size_t i = at.at(r.id[k]);
    fmax = std::max({fmax, std::abs(r.fx[k]), std::abs(r.fy[k]), std::abs(r.fz[k])});
    dmax = std::max({dmax, std::abs(p.fx[i] - r.fx[k]), std::abs(p.fy[i] - r.fy[k]), std::abs(p.fz[i] - r.fz[k])});
  }
  const double de = std::abs(s.potential_energy() - r.energy) / std::abs(r.energy);
  const auto& w = s.virial();
  const double wscale = std::abs(r.virial[0]) + std::abs(r.virial[1]) + std::abs(r.virial[2]);
  double dw = 0;
  for (int k = 0; k < 6; ++k) dw = std::max(dw, std::abs(w[k] - r.virial[k]) / wscale);
  std::printf("%s: %zu particles, energy %.12g eV (LAMMPS %.12g, rel %.2g), forces max rel %.2g, virial rel %.2g\n",
              name.c_str(), p.size(), s.potential_energy(), r.energy, de, dmax / fmax, dw);
  EXPECT_LT(de, 1e-10);
  EXPECT_LT(dmax / fmax, 1e-10);
  if (compare_virial) {
    EXPECT_LT(dw, 1e-10);
  }
}

dpd::Particles perturbed_crystal(int cells, double amplitude, std::uint64_t seed) {
  dpd::Particles p = dpd::fcc_block({cells, cells, cells}, test::kCoarseLattice, {0, 0, 0}, test::kCuMesoMass, 0, 1);
  particles::RngStream rng(seed, 0);
  const double l = cells * test::kCoarseLattice;
  for (std::size_t i = 0; i < p.size(); ++i) {
    p.x[i] = std::fmod(p.x[i] + amplitude * (rng.uniform() - 0.5) + l, l);
    p.y[i] = std::fmod(p.y[i] + amplitude * (rng.uniform() - 0.5) + l, l);
    p.z[i] = std::fmod(p.z[i] + amplitude * (rng.uniform() - 0.5) + l, l);
  }
  dpd::maxwell_velocities(p, 298.0, seed);
  return p;
}

dpd::DpdParams isothermal(double gamma, double rc) {
  dpd::DpdParams par;
  par.integrator = dpd::Integrator::velocity_verlet;
  par.gamma = gamma, par.cutoff = rc, par.temperature = 300, par.seed = 1;
  return par;
}

TEST(DpdLammps, SoftDpdFluidStepZero) {
  const test::SoftFluid f;
  const double l = std::cbrt(1500 / 3.0) * f.rc;
  dpd::Particles p = dpd::random_block(1500, {l, l, l}, {0, 0, 0}, f.mass, 0, 1, 5);
  dpd::maxwell_velocities(p, 300.0, 6);
  const dpd::System s(p, test::cube(l), f.potential(), isothermal(f.gamma(), f.rc), {.skin = 3.0});
  compare_step0(s, "soft_dpd");
}

TEST(DpdLammps, MorseCuMesoparticleCrystalStepZero) {
  const dpd::System s(perturbed_crystal(6, 0.6, 7), test::cube(6 * test::kCoarseLattice), test::cu_meso_morse(12.0),
                      isothermal(test::kSeedGamma, 12.0), {.skin = 1.0});
  compare_step0(s, "morse");
}

TEST(DpdLammps, MorseBoxUnderTwiceTheCutoffStepZero) {
  const dpd::System s(perturbed_crystal(3, 0.6, 8), test::cube(3 * test::kCoarseLattice), test::cu_meso_morse(12.0),
                      isothermal(test::kSeedGamma, 12.0), {.skin = 1.0});
  compare_step0(s, "morse_small_box");
}

TEST(DpdLammps, NmFormStepZero) {
  dpd::NmPotential nm;
  nm.e0 = 2.5, nm.r0 = 5.11, nm.n = 9, nm.m = 6, nm.rc = 12.0, nm.shift = true;
  nm.update_offset();
  const dpd::System s(perturbed_crystal(5, 0.6, 9), test::cube(5 * test::kCoarseLattice), nm,
                      isothermal(test::kSeedGamma, 12.0), {.skin = 1.0});
  compare_step0(s, "nm");
}

TEST(DpdLammps, OpenAxesStepZeroEnergyAndForces) {
  // A free-standing crystal block (open along x and z, periodic along y): LAMMPS
  // shrink-wraps the open axes, so the virial's volume differs; energy and forces agree.
  dpd::Particles p = perturbed_crystal(4, 0.4, 10);
  dpd::Domain d = test::cube(4 * test::kCoarseLattice, {false, true, false});
  const dpd::System s(p, d, test::cu_meso_morse(12.0), isothermal(test::kSeedGamma, 12.0), {.skin = 1.0});
  compare_step0(s, "morse_open", false);
}

TEST(DpdLammps, GammaZeroTrajectoryMatchesFixNve) {
  if (!app::dpd::lammps_available()) GTEST_SKIP() << "lmp (LAMMPS) is not installed: apt-get install lammps";
  dpd::System s(perturbed_crystal(5, 0.3, 11), test::cube(5 * test::kCoarseLattice), test::cu_meso_morse(12.0),
                isothermal(0.0, 12.0), {.skin = 1.0});
  const fs::path dir = scratch("nve");
  const double dt = 0.004;
  app::dpd::write_lammps_dpd(s, {.steps = 200, .dt = dt, .dump_forces = false, .dump_final = true}, dir.string());
  const auto r = app::dpd::run_lammps_dpd(dir.string());
  s.advance(200, dt);
  const dpd::Particles& p = s.particles();
  ASSERT_EQ(r.final_id.size(), p.size());
  std::map<long, std::size_t> at;
  for (std::size_t i = 0; i < p.size(); ++i) at[p.id[i]] = i;
  const double l = 5 * test::kCoarseLattice;
  double dx = 0, dv = 0, vmax = 0;
  for (std::size_t k = 0; k < r.final_id.size(); ++k) {
    const std::size_t i = at.at(r.final_id[k]);
    const double d[3] = {p.x[i] - r.x[k], p.y[i] - r.y[k], p.z[i] - r.z[k]};
    for (double c : d) dx = std::max(dx, std::abs(c - l * std::round(c / l)));
    dv = std::max({dv, std::abs(p.vx[i] - r.vx[k]), std::abs(p.vy[i] - r.vy[k]), std::abs(p.vz[i] - r.vz[k])});
    vmax = std::max({vmax, std::abs(r.vx[k]), std::abs(r.vy[k]), std::abs(r.vz[k])});
  }
  std::printf("200 NVE steps (gamma = 0): max |dx| %.2g A, max |dv| / max |v| %.2g\n", dx, dv / vmax);
  EXPECT_LT(dx, 1e-8 * test::kCoarseLattice);
  EXPECT_LT(dv / vmax, 1e-8);
}

}  // namespace
