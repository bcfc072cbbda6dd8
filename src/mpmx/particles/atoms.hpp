#pragma once
// Atoms of one MD system as structure-of-arrays (one contiguous array per field).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mpmx::particles {

struct Atoms {
  std::vector<double> x, y, z;     // positions (Angstrom)
  std::vector<double> vx, vy, vz;  // velocities (Angstrom/ps); leapfrog half-step values
  std::vector<double> fx, fy, fz;  // forces (eV/Angstrom)
  std::vector<int> type;           // 0-based type index into the potential's elements
  std::vector<std::int64_t> id;    // stable identity (survives spatial sorting)

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n);
  void push_back(double px, double py, double pz, int t, std::int64_t ident);
  // Reorders every field by `order` (new index k takes old index order[k]).
  void permute(const std::vector<std::size_t>& order);
};

}  // namespace mpmx::particles
