#pragma once
// Helpers shared by the MD tests: the Mishin Cu potential that Debian's lammps-data
// ships, a system's total energy, a scratch folder that lives as long as the test
// process, and whether LAMMPS (`lmp`) is there for the crosschecks.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "mpmx/md/potential/potential.hpp"
#include "mpmx/md/system.hpp"

namespace mpmx::test {

// The potential files of Debian's lammps-data, and the Mishin Cu one among them.
inline const std::string kLammpsPotentials = "/usr/share/lammps/potentials/";
inline const std::string kCuMishin = kLammpsPotentials + "Cu_mishin1.eam.alloy";

inline md::PotentialSpec copper_spec() {
  md::EamSpec spec;
  spec.file = kCuMishin;
  return spec;
}

inline md::Potential copper() { return md::Potential(copper_spec()); }

inline double total_energy(const md::System& s) { return s.potential_energy() + s.kinetic_energy(); }

// How many of two runs' numbers differ in any bit (every one when the counts differ):
// 0 for the same bits on any thread count.
inline std::size_t differing_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.size(); ++k) n += std::memcmp(&a[k], &b[k], sizeof(double)) != 0;
  return n;
}

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

// A correlated series' mean and its standard error, from ten block means.
struct BlockStats {
  double mean = 0, sem = 0;
};
inline BlockStats block_stats(const std::vector<double>& x) {
  const std::size_t nb = 10, len = x.size() / nb;
  std::vector<double> m(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    double sum = 0;
    for (std::size_t k = b * len; k < (b + 1) * len; ++k) sum += x[k];
    m[b] = sum / static_cast<double>(len);
  }
  BlockStats s;
  for (double y : m) s.mean += y / nb;
  double v = 0;
  for (double y : m) v += (y - s.mean) * (y - s.mean);
  s.sem = std::sqrt(v / (nb - 1) / nb);
  return s;
}

// A LAMMPS `write_dump ... custom id A B C modify sort id` file: id -> (A, B, C).
inline std::map<long, std::array<double, 3>> read_lammps_dump(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line;
  std::map<long, std::array<double, 3>> out;
  while (std::getline(in, line) && line.rfind("ITEM: ATOMS", 0) != 0) {
  }
  long id;
  double a, b, c;
  while (in >> id >> a >> b >> c) out[id] = {a, b, c};
  return out;
}

inline bool have_lmp() { return std::system("command -v lmp > /dev/null 2>&1") == 0; }

}  // namespace mpmx::test
