#pragma once
// Helpers shared by the continuum tests: read an example deck, edit it, run it in
// memory (no files), and read the by-time errors.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <toml++/toml.h>

#include "mpmx/app/mpm/deck.hpp"
#include "mpmx/app/mpm/run.hpp"

namespace mpmx::test {

inline std::string example(const std::string& name) {
  // Appended rather than summed: GCC 12 warns (-Warray-bounds) of operator+ on a
  // temporary here, wrongly.
  std::string path = MPMX_SOURCE_DIR;
  path += "/examples/";
  path += name;
  return path;
}

// Reads a deck file, lets `edit` change its TOML, and returns the checked config.
template <class Edit>
app::MpmConfig deck_with(const std::string& path, Edit edit) {
  toml::table t = toml::parse_file(path);
  edit(t);
  std::ostringstream os;
  os << t;
  return app::read_mpm_deck_text(os.str(), path);
}

inline app::MpmConfig deck(const std::string& path) {
  return deck_with(path, [](toml::table&) {});
}

inline app::RunResult run(const app::MpmConfig& c) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  return app::run_mpm(c, o);
}

// A 2-D or 3-D deck, in memory.
template <int Dim>
app::RunResultOf<Dim> run_dim(const app::MpmConfig& c) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  return app::run_mpm_dim<Dim>(c, o);
}

// The same particles to the bit: positions, velocities, stresses.
template <int Dim>
void expect_same_particles(const mpm::Particles<Dim>& a, const mpm::Particles<Dim>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (int d = 0; d < Dim; ++d) {
    EXPECT_EQ(a.x[d], b.x[d]);
    EXPECT_EQ(a.v[d], b.v[d]);
  }
  for (int k = 0; k < Dim * Dim; ++k) EXPECT_EQ(a.stress[k], b.stress[k]);
}

// Runs a 2-D or 3-D deck on one thread and on two and expects the same bits: the
// particles (positions, velocities, stresses) and the run's tallies. Returns both runs.
// `continuum_threads`: the continuum has points enough to use the two threads.
template <int Dim>
std::pair<app::RunResultOf<Dim>, app::RunResultOf<Dim>> same_on_one_and_two_threads(const app::MpmConfig& c,
                                                                                    bool continuum_threads = true) {
  app::RunOptions o;
  o.quiet = true;
  o.plot = false;
  o.threads = 1;
  auto one = app::run_mpm_dim<Dim>(c, o);
  o.threads = 2;
  auto two = app::run_mpm_dim<Dim>(c, o);
  if (continuum_threads) {
    EXPECT_EQ(two.state.threads, 2);
  }
  expect_same_particles(one.state.particles, two.state.particles);
  EXPECT_EQ(one.stress_work, two.stress_work);
  EXPECT_EQ(one.kinetic_final, two.kinetic_final);
  EXPECT_EQ(one.stored_final, two.stored_final);
  EXPECT_EQ(one.boundary_work, two.boundary_work);
  EXPECT_EQ(one.state.tallies.boundary_impulse, two.state.tallies.boundary_impulse);
  EXPECT_EQ(one.state.tallies.node_mass, two.state.tallies.node_mass);
  return {std::move(one), std::move(two)};
}

// A whole text file.
inline std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// What a shell command prints on stdout.
inline std::string capture(const std::string& cmd) {
  std::string out;
  if (FILE* f = popen(cmd.c_str(), "r")) {
    char buf[4096];
    while (std::size_t n = fread(buf, 1, sizeof buf, f)) out.append(buf, n);
    pclose(f);
  }
  return out;
}

// A1's standing wave at dt = 1, 50 times its CFL limit (allowed by raising cfl_limit),
// which blows up within a few steps; the energy-growth stop, which would end it first,
// out of the way; no reference and no record times.
inline app::MpmConfig blowing_up_a1() {
  return deck_with(example("A1_standing_wave_static.toml"), [](toml::table& t) {
    auto& time = *t["time"].as_table();
    time.insert_or_assign("dt", 1.0);
    time.insert_or_assign("end", 5000.0);
    time.insert_or_assign("cfl_limit", 100.0);
    time.insert_or_assign("energy_growth", 1e300);
    time.insert_or_assign("energy_growth_stop", 1e300);
    t["output"].as_table()->insert_or_assign("times", toml::array{});
    t.erase("reference");
  });
}

}  // namespace mpmx::test
