#pragma once
// Helpers shared by the MD tests: the Mishin Cu potential that Debian's lammps-data
// ships, and a scratch folder that lives as long as the test process.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mpmx/md/potential/potential.hpp"

namespace mpmx::test {

inline md::PotentialSpec copper_spec() {
  md::EamSpec spec;
  spec.file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";
  return spec;
}

inline md::Potential copper() { return md::Potential(copper_spec()); }

// A per-process folder under the system's temporary one, removed when the process ends.
inline const std::filesystem::path& scratch_root() {
  namespace fs = std::filesystem;
  static const struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("mpmx_test_" + std::to_string(getpid()));
    ~Scratch() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } scratch;
  return scratch.dir;
}

// Writes `text` to `name` in the scratch folder.
inline std::filesystem::path scratch_file(const std::string& name, const std::string& text) {
  std::filesystem::create_directories(scratch_root());
  std::ofstream(scratch_root() / name) << text;
  return scratch_root() / name;
}

}  // namespace mpmx::test
