// ctest-label: validation
// J1 in CI (VALIDATION.md J1): examples/J1_direct_md_tiny.toml through `mpmx md`. The
// lab-frame shock speed from the front's positions is within 10% of the copper
// Hugoniot's Us - up (Us = 3.94 + 1.49 up km/s: 5.165 km/s at up = 2.5); the shocked
// plateau's sigma_xx lies near rho0 Us up; the outputs (bins, images, profile) are there;
// and the run is the same to the byte whatever OMP_NUM_THREADS says.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mpmx/app/cli_checks.hpp"
#include "mpmx/core/machine.hpp"
#include "../md/md_test_util.hpp"
#include "cli_util.hpp"

namespace fs = std::filesystem;

namespace {
using mpmx::test::json_number;
using mpmx::test::slurp;

int run(const std::string& env, const fs::path& out) {
  fs::remove_all(out);
  const std::string cmd = env + " " + MPMX_BINARY + " md " + MPMX_SOURCE_DIR +
                          "/examples/J1_direct_md_tiny.toml --quiet --out " + out.string() + " > " +
                          (out.string() + ".log") + " 2>&1";
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

TEST(J1Tiny, ShockSpeedWithinTenPercentOfHugoniot) {
  const fs::path out = mpmx::test::scratch_root() / "j1_tiny";
  fs::create_directories(mpmx::test::scratch_root());
  ASSERT_EQ(run("OMP_NUM_THREADS=1", out), 0) << slurp(out.string() + ".log");
  const std::string json = slurp(out / "run.json");
  const double up = 2.5, hugoniot = 3.94 + 1.49 * up - up;  // km/s, lab frame
  const double us = json_number(json, "shock_speed_km_s");
  std::printf("J1 tiny: shock speed %.3f km/s (Hugoniot %.3f), peak %.1f GPa, plateau %.1f GPa\n", us, hugoniot,
              json_number(json, "peak_stress_gpa"), json_number(json, "plateau_stress_gpa"));
  EXPECT_NEAR(us, hugoniot, 0.10 * hugoniot);
  // rho0 Us up with Us = 3.94 + 1.49 up: 149 GPa of pressure; sigma_xx adds the
  // deviator (the seed's full-size peak: about 162 GPa). The tiny sample's columns are
  // small, so only the plateau is held, and to 20%.
  const double p_hugoniot = 8.93 * (3.94 + 1.49 * up) * up;
  EXPECT_NEAR(json_number(json, "plateau_stress_gpa"), 162.0, 0.2 * 162.0);
  EXPECT_GT(json_number(json, "plateau_stress_gpa"), p_hugoniot * 0.9);
  // md's default: every core, as run's, at most one a kAtomsPerMdThread atoms.
  const double atoms = json_number(json, "atoms");
  ASSERT_GT(atoms, 0.0) << json;  // absent, the rule below would give one thread whatever ran
  const int threads =
      mpmx::app::threads_for(static_cast<int>(mpmx::hardware_threads()), atoms, mpmx::app::kAtomsPerMdThread);
  EXPECT_EQ(json_number(json, "threads"), static_cast<double>(threads));
  EXPECT_GT(json_number(json, "md_atom_steps_per_second"), 0);
  EXPECT_TRUE(fs::exists(out / "md_bins.pvd"));
  EXPECT_TRUE(fs::exists(out / "vtk" / "md_bins_001500.vti"));
  EXPECT_TRUE(fs::exists(out / "bins" / "md_bins_001500.csv"));
  EXPECT_TRUE(fs::exists(out / "jet_profile.csv"));
  // The images are in nm, as the jet's continuum (nm_ps_GPa) beside them in ParaView:
  // 20 x 5 bins over the sample's length and period, given in Angstrom in run.json.
  const std::string vti = slurp(out / "vtk" / "md_bins_001500.vti");
  const auto at = vti.find("Spacing=\"");
  ASSERT_NE(at, std::string::npos);
  double dx = 0, dy = 0;
  ASSERT_EQ(std::sscanf(vti.c_str() + at, "Spacing=\"%lf %lf", &dx, &dy), 2);
  EXPECT_NEAR(dx, 0.1 * json_number(json, "length_A") / 20, 1e-9);
  EXPECT_NEAR(dy, 0.1 * json_number(json, "ly_A") / 5, 1e-9);
  EXPECT_NE(json.find("\"bins_series_length_unit\" : \"nm\""), std::string::npos);
}

TEST(J1Tiny, SameOutputsWhateverTheThreadCount) {
  const fs::path a = mpmx::test::scratch_root() / "j1_t1", b = mpmx::test::scratch_root() / "j1_t2";
  fs::create_directories(mpmx::test::scratch_root());
  ASSERT_EQ(run("OMP_NUM_THREADS=1", a), 0) << slurp(a.string() + ".log");
  ASSERT_EQ(run("OMP_NUM_THREADS=2", b), 0) << slurp(b.string() + ".log");
  for (const char* f : {"bins/md_bins_000750.csv", "bins/md_bins_001500.csv", "jet_profile.csv", "jet_front.csv",
                        "thermo.csv"})
    EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
}

// The full-size deck is a cluster run: `--check` passes it and prints the seed's size
// (about 2.8 million atoms) and its work; the scaled deck passes too.
TEST(J1Decks, FullAndScaledPassCheck) {
  auto check = [](const std::string& deck) {
    const std::string cmd = std::string(MPMX_BINARY) + " md " + MPMX_SOURCE_DIR + "/examples/" + deck + " --check 2>&1";
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    char buf[4096];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    const int st = pclose(p);
    EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << deck << ": " << out;
    return out;
  };
  const std::string full = check("J1_direct_md_full.toml");
  EXPECT_NE(full.find("2.802e+06 atoms, 30000 steps"), std::string::npos) << full;
  EXPECT_NE(full.find("8.4e+10 atom-steps"), std::string::npos) << full;
  const std::string scaled = check("J1_direct_md_s0p1.toml");
  EXPECT_NE(scaled.find("3000 steps"), std::string::npos) << scaled;
}
