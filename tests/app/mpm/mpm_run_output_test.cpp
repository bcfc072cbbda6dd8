// What a run leaves behind: run.json keys, CSV tables, and a NaN that stops the run
// with step, particle and field while the records already written stay whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mpm/mpm_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/profile.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/step.hpp"
#include "mpmx/mpm/viscosity.hpp"

using namespace mpmx;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / name;
  fs::remove_all(d);
  return d;
}

}  // namespace

TEST(RunOutput, WritesRunJsonAndTables) {
  const fs::path dir = fresh_dir("mpmx_run_output_test");
  auto c = test::deck_with(test::example("A1_standing_wave_static.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.3);
    t["output"].as_table()->insert_or_assign("times", toml::array{0.3});
    t["reference"].as_table()->insert_or_assign("times", toml::array{0.3});
  });
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.plot = false;
  app::run_mpm(c, o);
  const std::string json = test::slurp(dir / "run.json");
  for (const char* key : {"\"wall_seconds\"", "\"steps\" : 30000", "\"conservation\"", "\"mass\"",
                          "\"momentum\"", "\"energy\"", "\"errors\"", "\"velocity\"", "\"l1\"",
                          "\"l2\"", "\"version\"", "\"deck\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  const std::string particles = test::slurp(dir / "particles.csv");
  EXPECT_EQ(particles.rfind("time,particle,x,mass,volume,density,velocity,strain,stress,pressure", 0), 0u);
  EXPECT_NE(particles.find("ref_velocity"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "nodes.csv"));
  EXPECT_TRUE(fs::exists(dir / "energy.csv"));
  fs::remove_all(dir);
}

TEST(RunOutput, NanStopsTheRunNamingStepParticleAndField) {
  const fs::path dir = fresh_dir("mpmx_nan_test");
  // A time step 50 times the CFL limit blows up.
  auto c = test::blowing_up_a1();
  c.output_every = 1;
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.plot = false;
  std::string message;
  try {
    app::run_mpm(c, o);
  } catch (const RunError& e) {
    message = e.what();
  }
  // The blow-up is caught either as a volume turning negative or as a non-finite field,
  // whichever comes first; both name the field, the particle and the step.
  const bool named = message.find("non-finite") != std::string::npos ||
                     message.find("volume of particle") != std::string::npos;
  EXPECT_TRUE(named) << message;
  EXPECT_NE(message.find("particle "), std::string::npos) << message;
  EXPECT_NE(message.find("in step"), std::string::npos) << message;
  // run.json says it stopped; every record in the tables is whole (100 particle rows each).
  EXPECT_NE(test::slurp(dir / "run.json").find("\"status\" : \"stopped\""), std::string::npos);
  std::ifstream f(dir / "particles.csv");
  std::string line;
  std::getline(f, line);
  std::size_t rows = 0;
  while (std::getline(f, line)) {
    ++rows;
    EXPECT_EQ(std::count(line.begin(), line.end(), ','), 11) << line;  // ADMPM's 10 columns, body, material
  }
  EXPECT_GT(rows, 0u);
  EXPECT_EQ(rows % 100, 0u);
  fs::remove_all(dir);
}

TEST(Profiles, TanhStepSpansItsCells) {
  mpm::Profile p;
  p.kind = mpm::Profile::Kind::tanh;
  p.left = 2.0, p.right = 1.0, p.at = 0.5, p.cells = 26;
  const double dx = 0.01;
  EXPECT_DOUBLE_EQ(p(0.5, 0.0, 1.0, dx), 1.5);
  EXPECT_NEAR(p(0.5 - 13 * dx, 0.0, 1.0, dx), 2.0, 0.02);   // 98% across 13 cells
  EXPECT_NEAR(p(0.5 + 13 * dx, 0.0, 1.0, dx), 1.0, 0.02);
  EXPECT_GT(p(0.5 - 13 * dx, 0.0, 1.0, dx), 1.97);
  p.kind = mpm::Profile::Kind::step;
  EXPECT_EQ(p(0.49, 0.0, 1.0, dx), 2.0);
  EXPECT_EQ(p(0.51, 0.0, 1.0, dx), 1.0);
}

TEST(Viscosity, OnlyOnCompression) {  // dissertation sec. 6.3: 0.5 rho c |dv|, strain rate < 0
  auto c = test::deck(test::example("A1_standing_wave_static.toml"));
  auto s = app::make_state(c);
  auto& p = s.particles;
  p.grad_v[0][0] = -2.0;  // compressing
  p.grad_v[0][1] = +2.0;  // stretching
  mpm::artificial_viscosity(*s.material, 0.5, p);
  const double expect = 0.5 * p.density(0) * s.material->sound_speed(mpm::points(p), 0) * 2.0 * p.volume[0];
  EXPECT_NEAR(p.viscous_pressure[0], expect, 1e-15);
  EXPECT_EQ(p.viscous_pressure[1], 0.0);
}
