// The one-element EAM kernel on every vector path this machine runs (MPMX_ISA's names,
// `mpmx --version` lists them): forces, energy and virial (and the per-atom virial) are
// the scalar path's to the bit, in double and mixed precision, at the start and after a
// stretch of dynamics (new neighbour lists, atoms moved off their sites). The tiled form
// of one large system (SystemOptions::threaded) likewise, and the same bits for any
// thread count.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "mpmx/core/isa.hpp"
#include "mpmx/md/potential/eam_one_type.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"
#include "mpmx/particles/rng.hpp"

#include "md_test_util.hpp"

using namespace mpmx;

namespace {

// Every number the kernel gives, in order, as bits.
using Bits = std::vector<std::uint64_t>;

void add(Bits& out, const md::System& s) {
  const md::Atoms& a = s.atoms();
  for (const auto* v : {&a.fx, &a.fy, &a.fz, &s.per_atom_virial()})
    for (const double x : *v) out.push_back(std::bit_cast<std::uint64_t>(x));
  out.push_back(std::bit_cast<std::uint64_t>(s.potential_energy()));
  for (const double x : s.virial()) out.push_back(std::bit_cast<std::uint64_t>(x));
}

// How the system runs: one thread over the whole list, or tiled on `threads`.
struct Form {
  bool threaded = false;
  int threads = 1;
};
constexpr int kTileAtoms = 300;  // small tiles: many of them in a small box

// A 4 x 4 x 4 cell copper box (8 x 8 x 6 when tiled: six tiles), atoms shaken off
// their sites (so that neighbour counts vary, and with them the vector loops'
// remainders), at 600 K: its numbers now and after 40 steps of 2 fs.
md::Crystal shaken(int nx, int ny, int nz, std::uint64_t seed) {
  md::Crystal c = md::fcc(nx, ny, nz, 3.615);
  md::RngStream r(seed, 0);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    c.atoms.x[i] += 0.2 * (2 * r.uniform() - 1);
    c.atoms.y[i] += 0.2 * (2 * r.uniform() - 1);
    c.atoms.z[i] += 0.2 * (2 * r.uniform() - 1);
  }
  return c;
}

Bits run_path(const std::string& path, bool mixed, bool per_atom, Form form = {}) {
  mpmx::isa_use(path);
  EXPECT_EQ(md::eam_isa_dispatched(), path);
  const md::Crystal c = form.threaded ? shaken(8, 8, 6, 11) : shaken(4, 4, 4, 11);
  md::SystemOptions o;
  o.mixed_precision = mixed;
  o.per_atom = per_atom;
  o.threaded = form.threaded;
  o.threads = form.threads;
  o.tile_atoms = kTileAtoms;
  md::System s(c, test::copper(), o);
  s.thermalize(600, 3, 0);
  Bits out;
  add(out, s);
  s.advance(40, 0.002);
  add(out, s);
  return out;
}

// The first differing number's index, -1 for none.
long first_difference(const Bits& a, const Bits& b) {
  if (a.size() != b.size()) return 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != b[i]) return static_cast<long>(i);
  return -1;
}

class EamPath : public ::testing::TestWithParam<std::string> {
 protected:
  void TearDown() override { mpmx::isa_use(mpmx::isa_supported().front()); }
};

INSTANTIATE_TEST_SUITE_P(Isa, EamPath, ::testing::ValuesIn(mpmx::isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(EamPath, SameBitsAsTheScalarPath) {
  for (const bool mixed : {false, true})
    for (const bool per_atom : {false, true}) {
      const Bits scalar = run_path(mpmx::isa_compiled().back(), mixed, per_atom);
      const Bits here = run_path(GetParam(), mixed, per_atom);
      ASSERT_GT(scalar.size(), 1000u);
      EXPECT_EQ(first_difference(here, scalar), -1) << "mixed " << mixed << ", per_atom " << per_atom;
    }
}

TEST_P(EamPath, TiledSameBitsAsTheScalarPath) {
  for (const bool mixed : {false, true})
    for (const bool per_atom : {false, true}) {
      const Bits scalar = run_path(mpmx::isa_compiled().back(), mixed, per_atom, {true, 2});
      const Bits here = run_path(GetParam(), mixed, per_atom, {true, 2});
      ASSERT_GT(scalar.size(), 9000u);  // 1536 atoms
      EXPECT_EQ(first_difference(here, scalar), -1) << "mixed " << mixed << ", per_atom " << per_atom;
    }
}

// Threads take whole tiles and every atom adds its tiles' shares in tile order: 1, 2 and
// 3 threads give the same bits, forces, energies and virials included.
TEST(EamTiled, SameBitsForAnyThreadCount) {
  for (const bool per_atom : {false, true}) {
    const std::string path = mpmx::isa_supported().front();
    const Bits one = run_path(path, false, per_atom, {true, 1});
    EXPECT_EQ(first_difference(run_path(path, false, per_atom, {true, 2}), one), -1) << "per_atom " << per_atom;
    EXPECT_EQ(first_difference(run_path(path, false, per_atom, {true, 3}), one), -1) << "per_atom " << per_atom;
  }
}

// The tiled sums are the whole list's in another order: forces, energy, virial and the
// per-atom virial agree to round-off (same atoms, same start; before any dynamics could
// amplify the difference).
TEST(EamTiled, AgreesWithTheWholeListToRoundOff) {
  const md::Crystal c = shaken(8, 8, 6, 5);
  md::SystemOptions whole;
  whole.per_atom = true;
  md::SystemOptions tiled = whole;
  tiled.threaded = true;
  tiled.threads = 2;
  tiled.tile_atoms = kTileAtoms;
  const md::System a(c, test::copper(), whole), b(c, test::copper(), tiled);
  ASSERT_EQ(a.atoms().size(), b.atoms().size());
  double fmax = 0;
  for (std::size_t i = 0; i < a.atoms().size(); ++i) {
    ASSERT_EQ(a.atoms().id[i], b.atoms().id[i]);
    fmax = std::max({fmax, std::abs(a.atoms().fx[i]), std::abs(a.atoms().fy[i])});
    EXPECT_NEAR(a.atoms().fx[i], b.atoms().fx[i], 1e-12);
    EXPECT_NEAR(a.atoms().fy[i], b.atoms().fy[i], 1e-12);
    EXPECT_NEAR(a.atoms().fz[i], b.atoms().fz[i], 1e-12);
  }
  EXPECT_GT(fmax, 0.1);  // eV/A: the shaken atoms feel real forces
  EXPECT_NEAR(a.potential_energy(), b.potential_energy(), 1e-13 * std::abs(a.potential_energy()));
  for (int c6 = 0; c6 < 6; ++c6) EXPECT_NEAR(a.virial()[c6], b.virial()[c6], 1e-9);
  const std::vector<double>&va = a.per_atom_virial(), &vb = b.per_atom_virial();
  for (std::size_t k = 0; k < 6 * a.atoms().size(); ++k) EXPECT_NEAR(va[k], vb[k], 1e-11);
  mpmx::isa_use(mpmx::isa_supported().front());
}

// The paths differ from one another only in how they get there: the scalar path of
// double and mixed precision give different numbers (the test above compares like with
// like).
TEST(EamPathSanity, MixedPrecisionDiffersFromDouble) {
  EXPECT_NE(first_difference(run_path(mpmx::isa_compiled().back(), true, false),
                             run_path(mpmx::isa_compiled().back(), false, false)),
            -1);
  mpmx::isa_use(mpmx::isa_supported().front());
}

// MPMX_ISA picks the MD kernel's path as it does the 1-D kernels', and `mpmx --version`
// says which it took.
TEST(EamPathSanity, VersionNamesTheChosenPath) {
  for (const std::string& path : mpmx::isa_supported()) {
    const std::string cmd = "MPMX_ISA=" + path + " " + std::string(MPMX_BINARY) + " --version 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    std::string out;
    char buf[512];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    const int st = pclose(p);
    EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << out;
    EXPECT_NE(out.find("\nMD kernels: paths "), std::string::npos) << out;
    EXPECT_NE(out.find("; chosen: " + path + "\n"), std::string::npos) << out;
  }
}

}  // namespace
