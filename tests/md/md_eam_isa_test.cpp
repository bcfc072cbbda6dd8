// The one-element EAM kernel on every vector path this machine runs (MPMX_ISA's names,
// `mpmx --version` lists them): forces, energy and virial (and the per-atom virial) are
// the scalar path's to the bit, in double and mixed precision, at the start and after a
// stretch of dynamics (new neighbour lists, atoms moved off their sites).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "mpmx/md/lattice.hpp"
#include "mpmx/md/potential/eam_one_type.hpp"
#include "mpmx/md/rng.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/mpm/fused1d/isa.hpp"

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

// A 4 x 4 x 4 cell copper box, atoms shaken off their sites (so that neighbour counts
// vary, and with them the vector loops' remainders), at 600 K: its numbers now and
// after 40 steps of 2 fs.
Bits run(const std::string& path, bool mixed, bool per_atom) {
  mpm::shape::isa_use(path);
  EXPECT_EQ(md::eam_isa_dispatched(), path);
  md::Crystal c = md::fcc(4, 4, 4, 3.615);
  md::RngStream r(11, 0);
  for (std::size_t i = 0; i < c.atoms.size(); ++i) {
    c.atoms.x[i] += 0.2 * (2 * r.uniform() - 1);
    c.atoms.y[i] += 0.2 * (2 * r.uniform() - 1);
    c.atoms.z[i] += 0.2 * (2 * r.uniform() - 1);
  }
  md::SystemOptions o;
  o.mixed_precision = mixed;
  o.per_atom = per_atom;
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
  void TearDown() override { mpm::shape::isa_use(mpm::shape::isa_supported().front()); }
};

}  // namespace

INSTANTIATE_TEST_SUITE_P(Isa, EamPath, ::testing::ValuesIn(mpm::shape::isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST_P(EamPath, SameBitsAsTheScalarPath) {
  for (const bool mixed : {false, true})
    for (const bool per_atom : {false, true}) {
      const Bits scalar = run("scalar", mixed, per_atom);
      const Bits here = run(GetParam(), mixed, per_atom);
      ASSERT_GT(scalar.size(), 1000u);
      EXPECT_EQ(first_difference(here, scalar), -1) << "mixed " << mixed << ", per_atom " << per_atom;
    }
}

// The paths differ from one another only in how they get there: the scalar path of
// double and mixed precision give different numbers (the test above compares like with
// like).
TEST(EamPathSanity, MixedPrecisionDiffersFromDouble) {
  EXPECT_NE(first_difference(run("scalar", true, false), run("scalar", false, false)), -1);
  mpm::shape::isa_use(mpm::shape::isa_supported().front());
}

// MPMX_ISA picks the MD kernel's path as it does the 1-D kernels', and `mpmx --version`
// says which it took.
TEST(EamPathSanity, VersionNamesTheChosenPath) {
  for (const std::string& path : mpm::shape::isa_supported()) {
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
