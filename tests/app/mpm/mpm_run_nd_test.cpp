// ctest-label: unit
// What a 2-D run leaves for a user: VTK files that VTK itself reads back (points with
// every field, the stress as a 9-component tensor; the grid as image data), .pvd
// series, and run.json with the keys other checks rely on. Unknown scheme and material
// names are refused with the list of known ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>

#include "mpm/mpm_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/app/mpm/setup.hpp"

using namespace mpmx;
namespace fs = std::filesystem;

TEST(NdOutput, VtkFilesReadBackWithVtkAndRunJsonHasTheKeys) {
  const fs::path dir = fs::temp_directory_path() / "mpmx_nd_output_test";
  fs::remove_all(dir);
  const auto c = test::deck_with(test::example("N3_two_disks_cpdi.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.5);
  });
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.plot = false;
  const auto r = app::run_mpm_dim<2>(c, o);
  for (const char* f : {"run.json", "particles.pvd", "grid.pvd", "vtk/particles_000000.vtu", "vtk/particles_000050.vtu",
                        "vtk/grid_000050.vti"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  const std::string json = test::slurp(dir / "run.json");
  for (const char* key : {"\"dim\" : 2", "\"particles\"", "\"steps\" : 50", "\"wall_seconds\"",
                          "\"particle_steps_per_second\"", "\"mass\"", "\"momentum\"", "\"energy\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
  // The step's wall time by phase: every phase in run.json's "phases" block (read from the
  // block itself: "grid" is also a key of the deck's echo), timed, together within the
  // run's wall time.
  const std::size_t at = json.find("\"phases\" : {");
  ASSERT_NE(at, std::string::npos);
  const std::string block = json.substr(at, json.find('}', at) - at);
  for (std::size_t k = 0; k < mpm::kPhaseNames.size(); ++k) {
    std::string quoted(1, '"');
    quoted.append(mpm::kPhaseNames[k]).push_back('"');
    EXPECT_NE(block.find(quoted), std::string::npos) << quoted << " in " << block;
    EXPECT_GT(r.state.phases.seconds[k], 0.0) << mpm::kPhaseNames[k];
  }
  EXPECT_LE(r.state.phases.total(), r.wall_seconds);
  const std::string pvd = test::slurp(dir / "particles.pvd");
  EXPECT_NE(pvd.find("vtk/particles_000050.vtu"), std::string::npos);

  if (std::system("/usr/bin/python3 -c 'import vtk' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 is not installed (scripts/install-deps installs it)";
  const std::string script =
      "import vtk, sys\n"
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update(); o = r.GetOutput()\n"
      "s = o.GetPointData().GetArray('stress'); v = o.GetPointData().GetArray('velocity')\n"
      "g = vtk.vtkXMLImageDataReader(); g.SetFileName(sys.argv[2]); g.Update(); i = g.GetOutput()\n"
      "print(o.GetNumberOfPoints(), s.GetNumberOfComponents(), v.GetNumberOfComponents(), "
      "repr(s.GetComponent(7, 0)), repr(v.GetComponent(7, 1)), repr(o.GetPoint(7)[0]), i.GetDimensions()[0], "
      "i.GetDimensions()[1], i.GetPointData().GetArray('mass').GetNumberOfTuples(), repr(s.GetComponent(7, 8)), "
      "repr(o.GetPointData().GetArray('pressure').GetComponent(7, 0)))\n"
      // The labels: every point's body (two disks: 0 and 1), its id and its law.
      "d = o.GetPointData()\n"
      "print(' '.join(repr(d.GetArray(a).GetComponent(q, 0)) for a in ('body', 'id', 'material') "
      "for q in range(o.GetNumberOfPoints())))\n";
  const fs::path py = dir / "read.py";
  std::ofstream(py) << script;
  const std::string out = test::capture("/usr/bin/python3 " + py.string() + " " + (dir / "vtk/particles_000050.vtu").string() +
                                  " " + (dir / "vtk/grid_000050.vti").string());
  std::istringstream in(out);
  std::size_t n = 0;
  int sc = 0, vc = 0, nx = 0, ny = 0;
  double s7 = 0, v7 = 0, x7 = 0, zz7 = 0, p7 = 0;
  std::size_t nodes = 0;
  in >> n >> sc >> vc >> s7 >> v7 >> x7 >> nx >> ny >> nodes >> zz7 >> p7;
  ASSERT_TRUE(in) << out;
  const auto& p = r.state.particles;
  EXPECT_EQ(n, p.size());
  EXPECT_EQ(sc, 9);
  EXPECT_EQ(vc, 3);
  EXPECT_EQ(s7, p.stress[0][7]);  // bit for bit
  EXPECT_EQ(v7, p.v[1][7]);
  EXPECT_EQ(x7, p.x[0][7]);
  // Plane strain: sigma_zz in the tensor's zz slot, pressure -tr(sigma)/3 with it.
  EXPECT_EQ(zz7, p.stress_zz[7]);
  EXPECT_NE(zz7, 0.0);
  EXPECT_DOUBLE_EQ(p7, -(p.stress[0][7] + p.stress[3][7] + p.stress_zz[7]) / 3.0);
  EXPECT_EQ(nx, 21);
  EXPECT_EQ(ny, 21);
  EXPECT_EQ(nodes, 21u * 21u);
  // body, id and material of every point, as the run placed them: the left disk body 0.
  std::size_t left = 0;
  for (const int label : {0, 1, 2})
    for (std::size_t q = 0; q < n; ++q) {
      double v = -1;
      in >> v;
      ASSERT_TRUE(in) << out;
      const double want = label == 0 ? p.body[q] : label == 1 ? static_cast<double>(q) : p.law[q];
      EXPECT_EQ(v, want) << label << " " << q;
      if (label == 0) {
        EXPECT_EQ(p.body[q], r.state.particles.x[0][q] < 0.0 ? 0 : 1) << q;
        left += p.body[q] == 0;
      }
    }
  EXPECT_GT(left, 0u);
  EXPECT_LT(left, n);
  fs::remove_all(dir);
}

TEST(Registries, EveryNameTheGuideListsIsAcceptedAndUnknownOnesAreRefusedWithTheList) {
  for (const std::string& scheme : mpm::scheme_names()) {
    const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), [&](toml::table& t) {
      t["scheme"].as_table()->insert_or_assign("name", scheme);
      if (scheme == "ddmp_subpoints") t["scheme"].as_table()->insert_or_assign("subpoints", 2);
    });
    EXPECT_EQ(mpm::scheme_name(c.scheme.scheme), scheme);
  }
  try {
    test::deck_with(test::example("N3_two_disks_mpm.toml"),
                    [](toml::table& t) { t["scheme"].as_table()->insert_or_assign("name", "flip"); });
    ADD_FAILURE() << "an unknown scheme was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cpdi"), std::string::npos) << e.what();
  }
  const auto names = app::Materials::names();
  for (const char* m : {"linear_elastic", "cubic_elastic", "mie_gruneisen", "ideal_gas_isothermal",
                        "ideal_gas_adiabatic", "md_closure"})
    EXPECT_NE(std::find(names.begin(), names.end(), m), names.end()) << m;
  try {
    test::deck_with(test::example("N3_two_disks_mpm.toml"),
                    [](toml::table& t) { t["material"].as_table()->insert_or_assign("model", "rubber"); });
    ADD_FAILURE() << "an unknown material was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mie_gruneisen"), std::string::npos) << e.what();
  }
}

// dt = "cfl": every step's dt from the state, the records landing on their times.
TEST(NdOutput, CflTimeStepLandsOnTheRecordTimes) {
  const fs::path dir = fs::temp_directory_path() / "mpmx_nd_cfl_test";
  fs::remove_all(dir);
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), [](toml::table& t) {
    auto& time = *t["time"].as_table();
    time.insert_or_assign("dt", "cfl");
    time.insert_or_assign("cfl", 0.4);
    time.insert_or_assign("end", 0.5);
    auto& out = *t["output"].as_table();
    out.erase("every");
    out.insert_or_assign("times", toml::array{0.25});
  });
  EXPECT_TRUE(c.cfl_dt);
  // The first step's estimate: 0.4 dx / (c + |v|), c = sqrt(M / rho) of nu = 0.3.
  const double M = 1000.0 * 0.7 / (1.3 * 0.4), speed = std::sqrt(M / 1000.0) + 0.1 * std::sqrt(2.0);
  EXPECT_NEAR(c.dt, 0.4 * 0.05 / speed, 1e-12);
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.plot = false;
  const auto r = app::run_mpm_dim<2>(c, o);
  EXPECT_EQ(r.state.time, 0.5);
  EXPECT_GE(r.steps, std::llround(0.5 / c.dt));
  const std::string pvd = test::slurp(dir / "particles.pvd");
  EXPECT_NE(pvd.find("timestep=\"0.25\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("timestep=\"0.5\""), std::string::npos) << pvd;
  fs::remove_all(dir);
}

// Bodies: a box with a triangular notch cut from its right face (the copper jet's V),
// each point kept by its centre; a circle carries its own velocity.
TEST(NdBodies, BoxWithANotchAndACircle) {
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), [](toml::table& t) {
    toml::array bodies;
    bodies.push_back(toml::table{{"shape", "box"}, {"lower", toml::array{-0.5, -0.5}}, {"upper", toml::array{0.0, 0.5}}});
    bodies.push_back(toml::table{{"shape", "polygon"}, {"remove", true},
                                 {"vertices", toml::array{0.0, -0.5, 0.0, 0.5, -0.25, 0.0}}});
    bodies.push_back(toml::table{{"shape", "circle"}, {"center", toml::array{0.25, 0.0}}, {"radius", 0.1},
                                 {"velocity", toml::array{-1.0, 0.5}}});
    t.insert_or_assign("body", bodies);
  });
  const auto s = app::make_state<2>(c);
  // Centres on the 40 x 40 lattice of spacing 0.025 starting at -0.4875.
  std::size_t in_box = 0, in_circle = 0;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) {
      const double x = -0.4875 + 0.025 * i, y = -0.4875 + 0.025 * j;
      const bool notch = x > -0.25 + 0.5 * std::abs(y) && x < 0.0;  // the V: apex at (-0.25, 0)
      if (x <= 0.0 && !notch) ++in_box;
      if ((x - 0.25) * (x - 0.25) + y * y <= 0.01) ++in_circle;
    }
  EXPECT_EQ(s.particles.size(), in_box + in_circle);
  std::size_t moving = 0;
  for (std::size_t q = 0; q < s.particles.size(); ++q) {
    EXPECT_FALSE(s.particles.x[0][q] > -0.25 + 0.5 * std::abs(s.particles.x[1][q]) && s.particles.x[0][q] < 0.0)
        << "a point in the notch at " << s.particles.x[0][q] << ", " << s.particles.x[1][q];
    if (s.particles.v[0][q] == -1.0 && s.particles.v[1][q] == 0.5) ++moving;
  }
  EXPECT_EQ(moving, in_circle);
}

// A body with its own [body.material]: its points get that law's density and stress,
// the others the deck's; a removing region or a gas body among solids is refused.
TEST(NdBodies, BodiesTakeTheirOwnMaterial) {
  auto with_bodies = [](toml::table body_material) {
    return [body_material](toml::table& t) {
      toml::array bodies;
      bodies.push_back(toml::table{{"shape", "box"}, {"lower", toml::array{-0.5, -0.5}}, {"upper", toml::array{0.0, 0.5}},
                                   {"material", body_material}});
      bodies.push_back(toml::table{{"shape", "box"}, {"lower", toml::array{0.0, -0.5}}, {"upper", toml::array{0.5, 0.5}}});
      t.insert_or_assign("body", bodies);
    };
  };
  const toml::table soft{{"model", "linear_elastic"}, {"density", 250.0}, {"youngs_modulus", 10.0}, {"poisson_ratio", 0.3}};
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), with_bodies(soft));
  auto s = app::make_state<2>(c);
  ASSERT_EQ(s.particles.size(), 1600u);
  std::size_t light = 0;
  for (std::size_t q = 0; q < s.particles.size(); ++q) {
    const double rho = s.particles.mass[q] / s.particles.volume[q];
    if (s.particles.x[0][q] < 0.0) {
      EXPECT_DOUBLE_EQ(rho, 250.0);
      ++light;
    } else {
      EXPECT_DOUBLE_EQ(rho, 1000.0);
    }
  }
  EXPECT_EQ(light, 800u);
  EXPECT_EQ(s.material->name(), "linear_elastic+linear_elastic");
  // The same uniform stretch rate gives each block its own modulus' stress (the deck's
  // law holds the first block of points).
  ASSERT_GT(s.particles.x[0][0], 0.0);
  auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q) p.grad_v[0][q] = 1e-3;
  s.material->update_stress(mpm::points(p), 1.0);
  for (std::size_t q = 0; q < p.size(); ++q) {
    const double ratio = p.x[0][q] < 0.0 ? 10.0 / 1000.0 : 1.0;
    EXPECT_NEAR(p.stress[0][q], ratio * p.stress[0][0], 1e-12 * std::abs(p.stress[0][0]));
  }
  for (const auto& [table, word] :
       {std::pair{toml::table{{"model", "ideal_gas_isothermal"}, {"sound_speed", 1.0}}, std::string("solids and gases")}}) {
    try {
      test::deck_with(test::example("N3_two_disks_mpm.toml"), with_bodies(table));
      ADD_FAILURE() << "a gas body among solids was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  }
}

// A 2-D run stopped (as by Ctrl-C) and resumed from its checkpoint ends bit for bit as
// the uninterrupted run, its .pvd series continuing where it stopped: for every law whose
// per-point state a checkpoint carries (linear elastic; mie_gruneisen's energy, volume
// and deviator, alone and as two bodies' composite).
class NdResume : public ::testing::TestWithParam<const char*> {};

TEST_P(NdResume, CheckpointResumesBitForBit) {
  const fs::path dir = fs::temp_directory_path() / (std::string("mpmx_nd_resume_test_") + GetParam());
  fs::remove_all(dir);
  const auto deck = test::example(std::string(GetParam()) + ".toml");
  // 100 of the deck's steps, recorded at 50 and 100.
  const auto c = test::deck_with(deck, [](toml::table& t) {
    auto& time = *t["time"].as_table();
    time.insert_or_assign("end", 100 * time["dt"].value_or(0.0));
    auto& output = *t["output"].as_table();
    output.erase("times");
    output.insert_or_assign("every", 50);
  });
  const auto whole = test::run_dim<2>(c);
  app::RunOptions o;
  o.out_dir = dir.string();
  o.quiet = true;
  o.plot = false;
  o.stop_after = 60;
  const auto first = app::run_mpm_dim<2>(c, o);
  ASSERT_TRUE(first.interrupted);
  o.stop_after = 0;
  o.resume = true;
  const auto rest = app::run_mpm_dim<2>(c, o);
  EXPECT_EQ(rest.steps, whole.steps);
  for (int d = 0; d < 2; ++d) {
    EXPECT_EQ(rest.state.particles.x[d], whole.state.particles.x[d]);
    EXPECT_EQ(rest.state.particles.v[d], whole.state.particles.v[d]);
  }
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(rest.state.particles.stress[k], whole.state.particles.stress[k]);
    EXPECT_EQ(rest.state.particles.length[k], whole.state.particles.length[k]);
  }
  EXPECT_EQ(rest.stress_work, whole.stress_work);
  EXPECT_EQ(rest.stored_final, whole.stored_final);
  const std::string pvd = test::slurp(dir / "particles.pvd");
  EXPECT_NE(pvd.find("particles_000050.vtu"), std::string::npos);
  EXPECT_NE(pvd.find("particles_000100.vtu"), std::string::npos);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(EveryLaw, NdResume,
                         ::testing::Values("N3_two_disks_ddmp_subpoints", "N6_copper_planar_impact",
                                           "N6_aluminium_on_copper"));

// The keys of N2 and N4 are checked like every other: each refusal names its key.
TEST(NdDecks, ManufacturedConvergenceAndNormalKeysAreChecked) {
  auto refused = [](const std::string& deck, const std::function<void(toml::table&)>& edit, const std::string& word) {
    try {
      test::deck_with(test::example(deck), edit);
      ADD_FAILURE() << "accepted; expected a refusal naming " << word;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  const std::string n4 = "N4_manufactured_cpgimp.toml", n2 = "N2_rotated_shock_tube_cpdi.toml";
  refused(n4, [](toml::table& t) { t["manufactured"].as_table()->insert_or_assign("amplitude", 0.5); }, "amplitude");
  refused(n4, [](toml::table& t) { t["material"].as_table()->insert_or_assign("model", "mie_gruneisen"); },
          "manufactured");
  refused(n4, [](toml::table& t) { t["reference"].as_table()->insert_or_assign("fields", toml::array{"pressure"}); },
          "fields");
  refused(n4, [](toml::table& t) { t["convergence"].as_table()->insert_or_assign("levels", 20); }, "levels");
  refused(n4, [](toml::table& t) { t.erase("reference"); }, "levels");
  refused(n2, [](toml::table& t) {
    t["initial"].as_table()->get("pressure")->as_table()->insert_or_assign("normal", toml::array{0.0, 0.0});
  }, "normal");
  refused(n2, [](toml::table& t) { t["reference"].as_table()->insert_or_assign("name", "standing_wave"); }, "name");
  const auto c = test::deck(test::example(n4));
  EXPECT_EQ(c.convergence_levels, 4);
  EXPECT_TRUE(c.manufactured.on);
  const auto s = app::make_state<2>(c);  // started with the exact velocity
  ASSERT_TRUE(s.manufactured);
  const double pi = 3.141592653589793;
  for (std::size_t q = 0; q < s.particles.size(); q += 37)
    EXPECT_DOUBLE_EQ(s.particles.v[1][q], 0.01 * 100.0 * pi * std::sin(2.0 * pi * s.particles.x[1][q]));
}
