// ctest-label: unit
// The fields a user looks at (issue 46, item 3): the MD boxes' temperature and, in 1-D,
// their sigma_yy and sigma_zz in particles.csv and the .vtu, each the box's own value;
// the point's body and material; the MD boxes of chosen points as LAMMPS dumps OVITO
// reads (output.md_dump); Mie-Gruneisen's internal energy and plastic strain; output keys
// that would write nothing in a dimension refused there with the reason. And a run that
// stops writes its last state as a final record (item 4).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ms_test_util.hpp"
#include "mpmx/app/mpm/run.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/multiscale/md_closure.hpp"

// Helpers and tests in a namespace of their own: the unit tests build in unity batches.
namespace output_fields {

using namespace mpmx;
namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  for (std::string f; std::getline(ss, f, ',');) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// The rows of a CSV table as column -> value maps, and its header.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
};
CsvTable read_table(const std::string& path) {
  CsvTable t;
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  t.header = split(line);
  while (std::getline(f, line)) {
    const auto v = split(line);
    std::map<std::string, std::string> row;
    for (std::size_t k = 0; k < t.header.size() && k < v.size(); ++k) row[t.header[k]] = v[k];
    t.rows.push_back(row);
  }
  return t;
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}


// 1-D DDMP-MD at 300 K: each point's temperature, sigma_yy and sigma_zz are its box's
// (to the table's 10 digits), the box is hot and laterally stressed; the chosen points'
// boxes are dumped at step 0 and every 2 steps in LAMMPS's format.
TEST(OutputFields, OneDMdBarWritesTheBoxesTemperatureAndLateralStressesAndDumpsChosenBoxes) {
  auto c = test::deck_with(test::example("H2_strong_0K_256_small.toml"), [](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", 6);
    auto* md = t["material"]["md"].as_table();
    md->insert_or_assign("cells", 2);
    md->insert_or_assign("temperature", 300.0);
    md->insert_or_assign("relax_steps", 20);
    t["initial"]["strain"].as_table()->insert_or_assign("cells", 2.0);
    t["time"].as_table()->insert_or_assign("end", 0.4);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
    t["output"].as_table()->insert_or_assign("md_dump",
                                             toml::table{{"points", toml::array{1, 4}}, {"every", 2}});
    t.erase("reference");
  });
  ASSERT_EQ(c.md_dump_points, (std::vector<std::int64_t>{1, 4}));
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("output_fields_1d");
  const auto r = app::run_mpm(c, o);
  ASSERT_EQ(r.steps, 4);

  const CsvTable t = read_table(o.out_dir + "/particles.csv");
  const std::vector<std::string> tail{"pressure",    "body",           "material", "temperature",
                                      "internal_energy", "stress_yy", "stress_zz"};
  ASSERT_GE(t.header.size(), 16u);
  EXPECT_EQ(std::vector<std::string>(t.header.begin() + 9, t.header.begin() + 16), tail);
  const auto& closure = dynamic_cast<const multiscale::MdClosure<1>&>(*r.state.material);
  const double gpa = units::unit_system("nm_ps_GPa")->stress_GPa;
  const std::size_t n = r.state.particles.size();
  ASSERT_EQ(t.rows.size(), 2 * n);  // the records at t = 0 and the end
  for (std::size_t q = 0; q < n; ++q) {
    const auto& row = t.rows[n + q];
    const md::System& box = *closure.box(closure.groups().group_of(q));
    const double T = std::stod(row.at("temperature")), yy = std::stod(row.at("stress_yy")),
                 zz = std::stod(row.at("stress_zz"));
    EXPECT_NEAR(T, box.temperature(), 1e-9 * box.temperature()) << q;
    // The box's energy per unit mass above the 0 K crystal, in (km/s)^2 (1 eV/amu is
    // 1 / mvv2e (A/ps)^2, 10 A/ps a km/s).
    const double atoms = static_cast<double>(box.atoms().size()), m = box.type_mass()[0];
    const double e = ((box.potential_energy() + box.thermal_kinetic_energy()) / atoms -
                      closure.equilibrium().energy_per_atom) / m / (units::mvv2e * 100.0);
    EXPECT_NEAR(std::stod(row.at("internal_energy")), e, 1e-9 * std::abs(e)) << q;
    EXPECT_GT(e, 0.0) << q;
    EXPECT_GT(T, 50.0) << q;  // started at 2 x 300 K and relaxed: hot, not the 0 K lattice
    EXPECT_NEAR(yy, box.stress_gpa()[4] / gpa, 1e-9 * std::abs(yy) + 1e-12) << q;
    EXPECT_NEAR(zz, box.stress_gpa()[8] / gpa, 1e-9 * std::abs(zz) + 1e-12) << q;
    EXPECT_NE(yy, 0.0) << q;
    EXPECT_NE(yy, std::stod(row.at("stress"))) << q;  // the lateral stress, not sigma_xx again
    EXPECT_EQ(row.at("body"), "0");
    EXPECT_EQ(row.at("material"), "0");
  }

  // Dumps: steps 0, 2 and 4 of points 1 and 4, each a whole LAMMPS frame of the box.
  for (int q : {1, 4})
    for (int step : {0, 2, 4}) {
      const std::string path = fmt::format("{}/md_dump/point_{:06d}_{:09d}.dump", o.out_dir, q, step);
      ASSERT_TRUE(fs::exists(path)) << path;
      std::ifstream f(path);
      std::vector<std::string> lines;
      for (std::string l; std::getline(f, l);) lines.push_back(l);
      ASSERT_EQ(lines.size(), 9u + 32u) << path;  // 4 x 2^3 atoms
      EXPECT_EQ(lines[0], "ITEM: TIMESTEP");
      EXPECT_EQ(lines[1], std::to_string(step));
      EXPECT_EQ(lines[2], "ITEM: NUMBER OF ATOMS");
      EXPECT_EQ(lines[3], "32");
      EXPECT_EQ(lines[4], "ITEM: BOX BOUNDS pp pp pp");  // 1-D: the box stays orthogonal
      EXPECT_EQ(lines[8], "ITEM: ATOMS id type x y z vx vy vz");
      std::istringstream atom(lines[9]);
      double v[8];
      for (double& x : v) atom >> x;
      EXPECT_TRUE(atom) << lines[9];
      // Rows by id (the box's storage order is spatial): a reader that numbers atoms by
      // row, as LAMMPS's `rerun ... add yes` does, pairs each row with its own atom.
      for (int k = 0; k < 32; ++k) EXPECT_EQ(lines[9 + k].substr(0, lines[9 + k].find(' ')), std::to_string(k + 1));
    }
  // At the end, point 4's dumped box is its group's: its x extent the box's length.
  std::ifstream f(fmt::format("{}/md_dump/point_{:06d}_{:09d}.dump", o.out_dir, 4, 4));
  std::string l;
  for (int k = 0; k < 6; ++k) std::getline(f, l);
  double lo = 0, hi = 0;
  std::istringstream(l) >> lo >> hi;
  EXPECT_DOUBLE_EQ(hi - lo, closure.box(closure.groups().group_of(4))->box().lx);
}

// 2-D DDMP-MD: the .vtu carries the boxes' temperature and the labels; the dump of a
// box the flyer shears names its tilt as LAMMPS does (xy xz yz) where it has one.
TEST(OutputFields, TwoDMdFlyerWritesTemperatureBodiesAndDumps) {
  std::string text = test::flyer_2d_deck(0.0, 2);
  text.replace(text.find("[output]\ntimes = []"), 19,
               "[output]\ntimes = []\nmd_dump = { points = [0, 7] }");
  const auto c = app::read_mpm_deck_text(text, "flyer_2d");
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("output_fields_2d");
  const auto r = app::run_mpm_dim<2>(c, o);
  const std::string vtu = test::read_file(o.out_dir + "/vtk/particles_000002.vtu");
  for (const char* name : {"Name=\"temperature\"", "Name=\"body\"", "Name=\"material\"", "Name=\"id\""})
    EXPECT_NE(vtu.find(name), std::string::npos) << name;
  // The flyer's points are body 0, the target's body 1.
  const auto& p = r.state.particles;
  for (std::size_t q = 0; q < p.size(); ++q) EXPECT_EQ(p.body[q], p.x[0][q] < 1.1 ? 0 : 1) << q;
  for (int q : {0, 7})
    for (int step : {0, 2}) {
      const std::string d = test::read_file(fmt::format("{}/md_dump/point_{:06d}_{:09d}.dump", o.out_dir, q, step));
      ASSERT_FALSE(d.empty()) << q << " " << step;
      EXPECT_NE(d.find("ITEM: NUMBER OF ATOMS\n108\n"), std::string::npos);
      EXPECT_TRUE(d.find("ITEM: BOX BOUNDS pp pp pp\n") != std::string::npos ||
                  d.find("ITEM: BOX BOUNDS xy xz yz pp pp pp\n") != std::string::npos);
    }
}

// output.md_dump's fields: the dumped box's per-atom energy, stress and structure, as
// `mpmx md` writes them (OVITO's columns): their means are the box's own energy and stress
// at that step, and the crystal is labelled fcc; a field that is not one is refused.
TEST(OutputFields, MdDumpCarriesPerAtomFields) {
  std::string text = test::flyer_2d_deck(0.0, 2);
  text.replace(text.find("[output]\ntimes = []"), 19,
               "[output]\ntimes = []\nmd_dump = { points = [7], fields = [\"pe\", \"stress\", \"structure\"] }");
  const auto c = app::read_mpm_deck_text(text, "flyer_2d_fields");
  EXPECT_EQ(c.md_dump_fields, (std::vector<std::string>{"pe", "stress", "structure"}));
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("output_fields_2d_atoms");
  const auto r = app::run_mpm_dim<2>(c, o);
  const auto& closure = dynamic_cast<const multiscale::MdClosure<2>&>(*r.state.material);
  const md::System& box = *closure.box(closure.groups().group_of(7));
  std::istringstream d(test::read_file(fmt::format("{}/md_dump/point_{:06d}_{:09d}.dump", o.out_dir, 7, r.steps)));
  std::string line;
  while (std::getline(d, line) && line.rfind("ITEM: ATOMS", 0) != 0) {
  }
  EXPECT_EQ(line, "ITEM: ATOMS id type x y z vx vy vz pe sxx syy szz sxy sxz syz structure");
  double pe = 0, sxx = 0, syy = 0, sxy = 0;
  int atoms = 0, fcc = 0;
  for (double v[16]; std::getline(d, line); ++atoms) {
    std::istringstream in(line);
    for (double& x : v) in >> x;
    ASSERT_TRUE(in) << line;
    pe += v[8], sxx += v[9], syy += v[10], sxy += v[12];
    fcc += v[15] == 1.0;
  }
  ASSERT_EQ(atoms, static_cast<int>(box.atoms().size()));
  const md::Mat3 s = box.stress_gpa();
  EXPECT_NEAR(pe, box.potential_energy(), 1e-9 * std::abs(box.potential_energy()));
  EXPECT_NEAR(sxx / atoms, s[0], 1e-9 * std::abs(s[0]) + 1e-9);
  EXPECT_NEAR(syy / atoms, s[4], 1e-9 * std::abs(s[4]) + 1e-9);
  EXPECT_NEAR(sxy / atoms, s[1], 1e-9);
  EXPECT_GT(fcc, atoms / 2);  // 300 K fcc copper: most atoms keep their label

  std::string bad = test::flyer_2d_deck(0.0, 2);
  bad.replace(bad.find("[output]\ntimes = []"), 19, "[output]\ntimes = []\nmd_dump = { points = [7], fields = [\"ke\"] }");
  try {
    app::read_mpm_deck_text(bad, "flyer_2d_bad_field");
    ADD_FAILURE() << "a field that is not one was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("output.md_dump.fields"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'ke' is not a per-atom field"), std::string::npos) << e.what();
  }
}

// Two Mie-Gruneisen bodies (aluminium on copper, N6): VTK's own reader finds the body
// and material of every point, the internal energy and the plastic strain, equal to the
// run's; the flyer and the target are told apart.
TEST(OutputFields, TwoDBodiesOfTwoLawsReadBackWithVtk) {
  const auto c = test::deck_with(test::example("N6_aluminium_on_copper.toml"), [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 0.1);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
  });
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("output_fields_n6");
  const auto r = app::run_mpm_dim<2>(c, o);
  const auto& p = r.state.particles;
  std::size_t flyer = 0;
  for (std::size_t q = 0; q < p.size(); ++q) {
    const bool in_flyer = p.law[q] == 1;
    EXPECT_EQ(p.body[q], in_flyer ? 0 : 1) << q;
    flyer += in_flyer;
  }
  EXPECT_EQ(flyer, 40u * 4u * 4u);  // 2 mm of 0.05 mm cells x 4 cells, 2 x 2 points each
  // run.json names what the ids stand for: law 1 is the flyer's own aluminium.
  const std::string json = test::read_file(o.out_dir + "/run.json");
  const std::size_t at = json.find("\"materials\"");
  ASSERT_NE(at, std::string::npos) << json;
  EXPECT_NE(json.find("\"from\" : \"[material]\"", at), std::string::npos) << json.substr(at, 400);
  EXPECT_NE(json.find("\"from\" : \"[[body]] 0 [body.material]\"", at), std::string::npos) << json.substr(at, 400);
  EXPECT_LT(json.find("\"id\" : 0", at), json.find("\"id\" : 1", at));
  if (std::system("/usr/bin/python3 -c 'import vtk' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 is not installed (scripts/install-deps installs it)";
  const std::string script =
      "import vtk, sys\n"
      "r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update(); d = r.GetOutput().GetPointData()\n"
      "n = r.GetOutput().GetNumberOfPoints()\n"
      "for name in ['id', 'body', 'material', 'internal_energy', 'plastic_strain']:\n"
      "    a = d.GetArray(name)\n"
      "    print(name, a.GetNumberOfComponents(), ' '.join(repr(a.GetComponent(i, 0)) for i in range(n)))\n";
  const fs::path py = fs::path(o.out_dir) / "read.py";
  std::ofstream(py) << script;
  const std::string out = test::capture("/usr/bin/python3 " + py.string() + " " + o.out_dir + "/vtk/particles_000100.vtu");
  std::istringstream in(out);
  std::map<std::string, std::vector<double>> arrays;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string name;
    int components = 0;
    ls >> name >> components;
    EXPECT_EQ(components, 1) << name;
    for (double v; ls >> v;) arrays[name].push_back(v);
  }
  ASSERT_EQ(arrays.size(), 5u) << out;
  for (const auto& [name, values] : arrays) ASSERT_EQ(values.size(), p.size()) << name;
  const auto fields = r.state.material->point_fields(mpm::points(p));
  std::map<std::string, std::vector<double>> law;
  for (const auto& f : fields) law[f.name] = f.values;
  double hottest = 0.0, most_plastic = 0.0;
  for (std::size_t q = 0; q < p.size(); ++q) {
    EXPECT_EQ(arrays["id"][q], static_cast<double>(q));
    EXPECT_EQ(arrays["body"][q], p.body[q]);
    EXPECT_EQ(arrays["material"][q], p.law[q]);
    EXPECT_EQ(arrays["internal_energy"][q], law["internal_energy"][q]);  // bit for bit
    EXPECT_EQ(arrays["plastic_strain"][q], law["plastic_strain"][q]);
    hottest = std::max(hottest, arrays["internal_energy"][q]);
    most_plastic = std::max(most_plastic, arrays["plastic_strain"][q]);
  }
  // 0.1 us after a 2.5 km/s impact: the shocked metal holds energy and has yielded.
  EXPECT_GT(hottest, 0.0);
  EXPECT_GT(most_plastic, 0.0);
}

// A key that would write nothing in a dimension is refused there, with the key, the
// value and the reason; md_dump names points that exist, of a law that runs boxes.
TEST(OutputKeys, RefusedWhereTheyWouldWriteNothing) {
  const std::string two_d = test::example("N3_two_disks_mpm.toml");
  for (const char* key : {"particles", "nodes"}) {
    const std::string m = message_of([&] {
      test::deck_with(two_d, [&](toml::table& t) { t["output"].as_table()->insert_or_assign(key, true); });
    });
    EXPECT_NE(m.find(std::string("output.") + key), std::string::npos) << m;
    EXPECT_NE(m.find("true"), std::string::npos) << m;
    EXPECT_NE(m.find("1-D only"), std::string::npos) << m;
    EXPECT_NE(m.find("VTK"), std::string::npos) << m;
    // false says what the run does anyway.
    EXPECT_NO_THROW(
        test::deck_with(two_d, [&](toml::table& t) { t["output"].as_table()->insert_or_assign(key, false); }));
  }
  const std::string m = message_of([&] {
    test::deck_with(two_d, [](toml::table& t) {
      t["output"].as_table()->insert_or_assign("md_dump", toml::table{{"points", toml::array{3}}});
    });
  });
  EXPECT_NE(m.find("output.md_dump"), std::string::npos) << m;
  EXPECT_NE(m.find("md_closure"), std::string::npos) << m;
  const std::string range = message_of([] {
    test::deck_with(test::example("H2_strong_0K_256_small.toml"), [](toml::table& t) {
      t["output"].as_table()->insert_or_assign("md_dump", toml::table{{"points", toml::array{100000}}});
    });
  });
  EXPECT_NE(range.find("output.md_dump.points"), std::string::npos) << range;
  EXPECT_NE(range.find("100000"), std::string::npos) << range;
  EXPECT_NE(range.find("is not one of the deck's"), std::string::npos) << range;
}

// A 2-D run stopped by a point leaving the grid writes its last state, named final and
// last in particles.pvd, and says so in run.json; the message names the axis, step, time.
TEST(FinalRecord, A2dRunStoppedByAPointLeavingTheGridWritesItsLastState) {
  const auto c = test::deck_with(test::example("N3_two_disks_mpm.toml"), [](toml::table& t) {
    toml::array bodies;
    bodies.push_back(toml::table{{"shape", "circle"}, {"center", toml::array{0.0, 0.3}}, {"radius", 0.1},
                                 {"velocity", toml::array{0.0, 40.0}}});
    t.insert_or_assign("body", bodies);
    t["time"].as_table()->insert_or_assign("end", 0.05);
    t["time"].as_table()->insert_or_assign("cfl_limit", 100.0);
    t["output"].as_table()->insert_or_assign("every", 1000);
  });
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("final_record_2d");
  const std::string m = message_of([&] { app::run_mpm_dim<2>(c, o); });
  ASSERT_NE(m.find("left the grid (y = "), std::string::npos) << m;
  EXPECT_NE(m.find("step "), std::string::npos) << m;
  EXPECT_NE(m.find("t = "), std::string::npos) << m;
  const std::string json = test::read_file(o.out_dir + "/run.json");
  const std::size_t at = json.find("\"final_record\"");
  ASSERT_NE(at, std::string::npos) << json;
  EXPECT_NE(json.find("left the grid", at), std::string::npos);
  EXPECT_NE(json.find("\"step\"", at), std::string::npos);
  EXPECT_NE(json.find("\"time\"", at), std::string::npos);
  std::string final_vtu;
  for (const auto& e : fs::directory_iterator(o.out_dir + "/vtk"))
    if (e.path().filename().string().rfind("particles_final_", 0) == 0) final_vtu = e.path().filename().string();
  ASSERT_FALSE(final_vtu.empty());
  const std::string pvd = test::read_file(o.out_dir + "/particles.pvd");
  EXPECT_NE(pvd.find("vtk/" + final_vtu), std::string::npos) << pvd;
  EXPECT_GT(pvd.find("vtk/" + final_vtu), pvd.find("vtk/particles_000000.vtu"));  // listed last
  EXPECT_NE(test::read_file(o.out_dir + "/vtk/" + final_vtu).find("Name=\"body\""), std::string::npos);

  // Resumed from a checkpoint before the failure, the run stops again the same way: one
  // final record in the series, the earlier one replaced.
  app::RunOptions every = o;
  every.out_dir = test::scratch_dir("final_record_2d_resumed");
  every.checkpoint_every = 1;
  EXPECT_EQ(message_of([&] { app::run_mpm_dim<2>(c, every); }), m);
  every.resume = true;
  EXPECT_EQ(message_of([&] { app::run_mpm_dim<2>(c, every); }), m);
  const std::string again = test::read_file(every.out_dir + "/particles.pvd");
  EXPECT_EQ(again.find("_final_"), again.rfind("_final_")) << again;
  EXPECT_NE(again.find("vtk/" + final_vtu), std::string::npos) << again;
  std::size_t finals = 0;
  for (const auto& e : fs::directory_iterator(every.out_dir + "/vtk"))
    finals += e.path().filename().string().find("_final_") != std::string::npos;
  EXPECT_EQ(finals, 2u);  // its .vtu and .vti
}

// A 1-D run whose step is far past the CFL limit blows up: its last state is written as
// final_particles.csv (every point, the regular columns), and run.json says so.
TEST(FinalRecord, A1dRunThatBlowsUpWritesItsLastStateAsFinalTables) {
  const auto c = test::blowing_up_a1();
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.out_dir = test::scratch_dir("final_record_1d");
  const std::string m = message_of([&] { app::run_mpm(c, o); });
  ASSERT_FALSE(m.empty());
  EXPECT_NE(m.find("in step"), std::string::npos) << m;
  const CsvTable last = read_table(o.out_dir + "/final_particles.csv");
  const CsvTable regular = read_table(o.out_dir + "/particles.csv");
  EXPECT_EQ(last.header, regular.header);
  ASSERT_EQ(last.rows.size(), 100u);  // one record: every point
  EXPECT_EQ(regular.rows.size(), 100u);  // t = 0 only: the run stopped before its end
  const std::string time = last.rows.front().at("time");
  EXPECT_GT(std::stod(time), 0.0);
  for (const auto& row : last.rows) EXPECT_EQ(row.at("time"), time);
  const std::string json = test::read_file(o.out_dir + "/run.json");
  const std::size_t at = json.find("\"final_record\"");
  ASSERT_NE(at, std::string::npos) << json;
  EXPECT_NE(json.find("final_particles.csv", at), std::string::npos) << json;
  EXPECT_NE(json.find("\"status\" : \"stopped\""), std::string::npos);
}

}  // namespace output_fields
