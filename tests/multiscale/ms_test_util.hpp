#pragma once
// Helpers shared by the multiscale tests: a tiny DDMP-MD bar cut from an H deck (few
// points, small boxes, a few steps) that runs in a second even under the sanitizers.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "../md/md_test_util.hpp"
#include "../mpm/mpm_test_util.hpp"
#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/mpm/particles.hpp"
#include "mpmx/multiscale/md_closure_model.hpp"

namespace mpmx::test {

// The MD closure's configuration of a deck whose material is md_closure.
inline multiscale::MdClosureConfig closure_config(const app::MpmConfig& c) {
  return dynamic_cast<const multiscale::MdClosureModel&>(*c.material.spec).md;  // a test may cast
}

// A figure the run's md_closure reports (its Subscale): md.atom_steps_unshared, ...
template <class Result>
std::variant<std::int64_t, double> closure_figure(const Result& r, const std::string& key) {
  for (const auto& [k, v] : r.state.material->subscale()->figures())
    if (k == key) return v;
  return std::nan("");
}

// The H2 small bar with `points` points of 4 x cells^3 atoms for `steps` steps of 0.1 ps.
inline app::MpmConfig tiny_bar(int points, int cells, int steps, double temperature = 0.0) {
  return deck_with(example("H2_strong_0K_256_small.toml"), [&](toml::table& t) {
    t["grid"].as_table()->insert_or_assign("cells", points);
    auto* md = t["material"]["md"].as_table();
    md->insert_or_assign("cells", cells);
    md->insert_or_assign("temperature", temperature);
    md->insert_or_assign("relax_steps", temperature > 0 ? 20 : 0);
    t["initial"]["strain"].as_table()->insert_or_assign("cells", 2.0);
    t["time"].as_table()->insert_or_assign("end", 0.1 * steps);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
    t.erase("reference");
  });
}

// Two points of unit mass and volume at rest, the first unstrained and the second at
// engineering strain `strain` along x: what a closure's initialize takes.
inline mpm::Particles<1> two_points(double strain) {
  mpm::Particles<1> p;
  p.resize(2);
  p.strain[0] = {0.0, strain};
  p.mass = {1.0, 1.0};
  p.volume = {1.0, 1.0};
  return p;
}

// A copper flyer (x < 1.1 nm) moving at 0.5 km/s into copper at rest, 2-D DDMP-MD: 4 x 2
// cells, one point per cell, each point a box of 4 x 3^3 = 108 atoms; steps of 0.1 ps.
inline std::string flyer_2d_deck(double temperature, int steps, bool consistent = true) {
  return fmt::format(R"(
[case]
id = "md_closure_2d"
units = "nm_ps_GPa"
[grid]
dim = 2
lower = [0.0, 0.0]
upper = [4.4, 2.2]
cells = [4, 2]
[particles]
per_cell = [1, 1]
[[body]]
shape = "box"
lower = [0.0, 0.0]
upper = [1.1, 2.2]
velocity = [0.5, 0.0]
[[body]]
shape = "box"
lower = [1.1, 0.0]
upper = [4.4, 2.2]
[scheme]
name = "cpdi"
[material]
model = "md_closure"
[material.potential]
style = "eam"
file = "Cu_mishin1.eam.alloy"
elements = ["Cu"]
[material.md]
cells = 3
temperature = {}
relax_steps = {}
energy_consistency = {}
[boundary]
y_lower = {{ type = "roller" }}
y_upper = {{ type = "roller" }}
[time]
dt = 0.1
end = {}
[output]
times = []
)",
                     temperature, temperature > 0 ? 20 : 0, consistent ? "true" : "false", 0.1 * steps);
}

// A fresh, empty folder in the scratch folder.
inline std::string scratch_dir(const std::string& name) {
  const std::filesystem::path d = scratch_root() / name;
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

// A quiet run without figures into a fresh scratch folder `name` on `threads` threads,
// stopped with a checkpoint after `stop_after` steps (0: to the end).
inline app::RunOptions stopping_run(const std::string& name, std::int64_t stop_after, int threads = 1) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = threads;
  o.out_dir = scratch_dir(name);
  o.stop_after = stop_after;
  return o;
}

// A whole file as text ("" when absent).
inline std::string read_file(const std::string& path) {
  std::ifstream f(path);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

}  // namespace mpmx::test
