#pragma once
// Helpers shared by the continuum tests: read an example deck, edit it, run it in
// memory (no files), and read the by-time errors.
#include <fstream>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "mpmx/io/mpm_deck.hpp"
#include "mpmx/mpm/run.hpp"

namespace mpmx::test {

inline std::string example(const std::string& name) {
  return std::string(MPMX_SOURCE_DIR) + "/examples/" + name;
}

// Reads a deck file, lets `edit` change its TOML, and returns the checked config.
template <class Edit>
mpm::MpmConfig deck_with(const std::string& path, Edit edit) {
  toml::table t = toml::parse_file(path);
  edit(t);
  std::ostringstream os;
  os << t;
  return io::read_mpm_deck_text(os.str(), path);
}

inline mpm::MpmConfig deck(const std::string& path) {
  return deck_with(path, [](toml::table&) {});
}

inline mpm::RunResult run(const mpm::MpmConfig& c) {
  mpm::RunOptions o;
  o.quiet = true;
  o.plot = false;
  return mpm::run_mpm(c, o);
}

// A 2-D or 3-D deck, in memory.
template <int Dim>
mpm::RunResultOf<Dim> run_dim(const mpm::MpmConfig& c) {
  mpm::RunOptions o;
  o.quiet = true;
  o.plot = false;
  return mpm::run_mpm_dim<Dim>(c, o);
}

// A whole text file.
inline std::string slurp(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace mpmx::test
