// EAM/LJ/Sutton-Chen: file readers (and their error messages), forces as minus the
// energy gradient, Newton's third law (eq. 5.24), virial as the strain derivative.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/lattice.hpp"
#include "mpmx/md/potential/eam_file.hpp"
#include "mpmx/md/rng.hpp"
#include "mpmx/md/system.hpp"

#include "md_test_util.hpp"

using namespace mpmx::md;
namespace fs = std::filesystem;

namespace {

const std::string kPot = "/usr/share/lammps/potentials/";

std::string read_text(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string temp_file(const std::string& name, const std::string& text) {
  return mpmx::test::scratch_file(name, text).string();
}

std::string error_of(const std::string& path) {
  try {
    read_eam(path);
  } catch (const mpmx::InputError& e) {
    return e.what();
  }
  return "no error";
}

Crystal perturbed(int n, double a, std::uint64_t seed, double amp = 0.1) {
  Crystal c = fcc(n, n, n, a);
  RngStream r(seed, 0);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    c.atoms.x[i] += amp * (2 * r.uniform() - 1);
    c.atoms.y[i] += amp * (2 * r.uniform() - 1);
    c.atoms.z[i] += amp * (2 * r.uniform() - 1);
  }
  return c;
}

// Central difference of the energy against each force component of a few atoms.
void expect_forces_are_gradient(const Potential& pot, const Crystal& c, double tol) {
  SystemOptions o;
  o.sort_atoms = false;
  System s(c, pot, o);
  const double h = 1e-5;
  for (int i : {0, 7, 13}) {
    for (int d = 0; d < 3; ++d) {
      auto energy_at = [&](double delta) {
        System t = s;
        auto& a = t.edit_atoms();
        (d == 0 ? a.x : d == 1 ? a.y : a.z)[i] += delta;
        t.refresh();
        return t.potential_energy();
      };
      const double fd = -(energy_at(h) - energy_at(-h)) / (2 * h);
      const double f = (d == 0 ? s.atoms().fx : d == 1 ? s.atoms().fy : s.atoms().fz)[i];
      EXPECT_NEAR(f, fd, tol) << "atom " << i << " component " << d;
    }
  }
  double sx = 0, sy = 0, sz = 0;
  for (std::size_t i = 0; i < s.atoms().size(); ++i)
    sx += s.atoms().fx[i], sy += s.atoms().fy[i], sz += s.atoms().fz[i];
  EXPECT_NEAR(sx, 0.0, 1e-10);
  EXPECT_NEAR(sy, 0.0, 1e-10);
  EXPECT_NEAR(sz, 0.0, 1e-10);
}

}  // namespace

TEST(EamFile, ReadsEveryShippedEamFile) {
  if (!fs::exists(kPot)) GTEST_SKIP() << "lammps-data not installed";
  int n = 0;
  for (const auto& e : fs::directory_iterator(kPot)) {
    const auto name = e.path().filename().string();
    if (!(name.ends_with(".eam") || name.ends_with(".eam.alloy") || name.ends_with(".eam.fs"))) continue;
    EXPECT_NO_THROW(read_eam(e.path().string())) << name;
    ++n;
  }
  EXPECT_GE(n, 10);
}

TEST(EamFile, SetflHeaderAndTables) {
  const auto t = read_eam(kPot + "Cu_mishin1.eam.alloy");
  EXPECT_EQ(t.format, "setfl");
  ASSERT_EQ(t.elements.size(), 1u);
  EXPECT_EQ(t.elements[0], "Cu");
  EXPECT_DOUBLE_EQ(t.masses[0], 63.55);
  EXPECT_EQ(t.nrho, 10001);
  EXPECT_EQ(t.nr, 10001);
  EXPECT_NEAR(t.cut, 5.50679, 1e-12);
  const auto f = read_eam(kPot + "CuZr_mm.eam.fs");
  EXPECT_EQ(f.format, "fs");
  EXPECT_EQ(f.rhor.size(), 4u);
  EXPECT_EQ(f.z2r.size(), 3u);
  const auto u = read_eam(kPot + "Cu_u3.eam");
  EXPECT_EQ(u.format, "funcfl");
  EXPECT_EQ(u.nr, 499);  // LAMMPS's int(rmax/dr + 0.5)
}

TEST(EamFile, TruncatedFileNamesFileLineAndExpectation) {
  const auto text = read_text(kPot + "Cu_mishin1.eam.alloy");
  // Keep the header and a few hundred lines: F(rho) ends early.
  std::size_t pos = 0;
  for (int l = 0; l < 300; ++l) pos = text.find('\n', pos) + 1;
  const auto p = temp_file("Cu_cut.eam.alloy", text.substr(0, pos));
  const auto msg = error_of(p);
  EXPECT_NE(msg.find("Cu_cut.eam.alloy:300:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("file ends early: expected 10001 values of F(rho) of Cu"), std::string::npos) << msg;
}

TEST(EamFile, BadValuesAreNamed) {
  auto text = read_text(kPot + "Cu_mishin1.eam.alloy");
  // Corrupt a number on line 8.
  std::size_t pos = 0;
  for (int l = 0; l < 7; ++l) pos = text.find('\n', pos) + 1;
  text.insert(pos, "abc ");
  auto msg = error_of(temp_file("Cu_bad.eam.alloy", text));
  EXPECT_NE(msg.find("Cu_bad.eam.alloy:8: expected a number (F(rho) of Cu), found 'abc'"), std::string::npos)
      << msg;
  msg = error_of(temp_file("Cu_hdr.eam.alloy", "a\nb\nc\n2 Cu\n"));
  EXPECT_NE(msg.find("Cu_hdr.eam.alloy:4: expected 2 element names after N, found 1"), std::string::npos)
      << msg;
  msg = error_of(temp_file("Cu_grid.eam.alloy", "a\nb\nc\n1 Cu\n100 0.1 x 0.1 5\n"));
  EXPECT_NE(msg.find("Cu_grid.eam.alloy:5: expected an integer (nr), found 'x'"), std::string::npos) << msg;
  msg = error_of(temp_file("Cu_short.eam", "comment\n29 63.55\n"));
  EXPECT_NE(msg.find("Cu_short.eam:2: file ends early: expected 'nrho drho nr dr cutoff' on line 3"),
            std::string::npos)
      << msg;
  msg = error_of(temp_file("Cu.txt", "x"));
  EXPECT_NE(msg.find("cannot tell the EAM format"), std::string::npos) << msg;
  msg = error_of("/nonexistent/Cu.eam");
  EXPECT_NE(msg.find("/nonexistent/Cu.eam: cannot open"), std::string::npos) << msg;
}

TEST(EamFile, UnknownElementIsAnInputError) {
  PotentialSpec s;
  s.file = kPot + "Cu_mishin1.eam.alloy";
  s.elements = {"Zr"};
  try {
    Potential p(s);
    FAIL() << "no error";
  } catch (const mpmx::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 'Zr' is not in the file"), std::string::npos);
  }
}

TEST(EamForces, AreMinusEnergyGradientAndSumToZero) {
  PotentialSpec s;
  s.file = kPot + "Cu_mishin1.eam.alloy";
  expect_forces_are_gradient(Potential(s), perturbed(3, 3.615, 1), 2e-6);
  s.file = kPot + "Cu_u3.eam";
  expect_forces_are_gradient(Potential(s), perturbed(3, 3.615, 2), 2e-6);
}

TEST(EamForces, FinnisSinclairAlloyForces) {
  PotentialSpec s;
  s.file = kPot + "CuZr_mm.eam.fs";
  s.elements = {"Cu", "Zr"};
  Crystal c = perturbed(3, 3.8, 3);
  for (std::size_t i = 0; i < c.atoms.size(); i += 3) c.atoms.type[i] = 1;
  expect_forces_are_gradient(Potential(s), c, 2e-6);
}

TEST(PairForces, LennardJonesAndSuttonChen) {
  PotentialSpec lj;
  lj.style = "lj";
  lj.epsilon = 0.0104, lj.sigma = 3.4, lj.cutoff = 8.5, lj.mass = 39.95;
  expect_forces_are_gradient(Potential(lj), perturbed(3, 5.26, 4), 1e-7);
  PotentialSpec sc;  // Sutton-Chen Cu (Sutton & Chen 1990)
  sc.style = "sutton_chen";
  sc.epsilon = 1.2382e-2, sc.a = 3.61, sc.c = 39.432, sc.n = 9, sc.m = 6, sc.cutoff = 7.0, sc.mass = 63.55;
  expect_forces_are_gradient(Potential(sc), perturbed(4, 3.61, 5), 2e-6);
}

// The potential part of eq. 2.25 is the strain derivative of the energy:
// sigma_ab = (1/V) dE/d(eps_ab) for a homogeneous deformation of atoms and box.
TEST(Stress, VirialIsStrainDerivativeOfEnergy) {
  PotentialSpec s;
  s.file = kPot + "Cu_mishin1.eam.alloy";
  Potential pot(s);
  Crystal c = perturbed(4, 3.62, 6, 0.05);
  c.box.xy = 0.7;  // sheared images
  c.box.xz = -0.4;
  c.box.yz = 0.3;
  SystemOptions o;
  o.sort_atoms = false;
  System sys(c, pot, o);
  const Mat3 sigma = sys.stress();  // atoms at rest: potential part only
  const double h = 1e-6;
  for (auto [a, b] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}}) {
    auto energy = [&](double e) {
      // Upper-triangular displacement gradient: x_a += e x_b, box h <- (I + e E_ab) h.
      Mat3 g{};
      g[3 * a + b] = e;
      System t = sys;
      auto& at = t.edit_atoms();
      for (std::size_t i = 0; i < at.size(); ++i) {
        const double p[3] = {at.x[i], at.y[i], at.z[i]};
        (a == 0 ? at.x : a == 1 ? at.y : at.z)[i] += e * p[b];
      }
      Box bx = t.box();
      bx.deform(g, 1.0);
      t.set_box(bx);
      t.refresh();
      return t.potential_energy();
    };
    const double dE = (energy(h) - energy(-h)) / (2 * h);
    EXPECT_NEAR(sigma[3 * a + b], dE / sys.box().volume(), 2e-7) << a << b;
  }
}

// Mixed precision (float pair arithmetic, double sums): energy within 1e-5 relative,
// forces within 1e-4 of the largest, and still energy-conserving dynamics.
TEST(EamForces, MixedPrecisionAgreesWithDouble) {
  PotentialSpec s;
  s.file = kPot + "Cu_mishin1.eam.alloy";
  Potential pot(s);
  const Crystal c = perturbed(5, 3.615, 9);
  SystemOptions o;
  System d(c, pot, o);
  o.mixed_precision = true;
  System m(c, pot, o);
  EXPECT_NEAR(m.potential_energy() / d.potential_energy(), 1.0, 1e-5);
  double fmax = 0, diff = 0;
  for (std::size_t i = 0; i < d.atoms().size(); ++i) {
    fmax = std::max(fmax, std::abs(d.atoms().fx[i]));
    diff = std::max(diff, std::abs(d.atoms().fx[i] - m.atoms().fx[i]));
  }
  EXPECT_LT(diff, 1e-4 * fmax);
  m.thermalize(300, 1, 1);
  const double e0 = m.potential_energy() + m.kinetic_energy();
  m.advance(500, 0.001);
  EXPECT_NEAR((m.potential_energy() + m.kinetic_energy() - e0) / m.atoms().size(), 0.0, 5e-5);
}
