#pragma once
// DPD mesoparticles as structure-of-arrays: particles::Atoms' kinematics (positions,
// velocities, forces, type, id) plus, per particle, a mass, an internal energy (DPDE,
// seed 004 sec. 2.2) and the rigid group it belongs to (kMobile when it is free).
//
// Particles is a particles::Atoms so that the neighbour lists both engines use
// (particles::Neighbors) serve it unchanged; resize, push_back and permute here keep the
// extra fields in step (call them on a Particles, not through a particles::Atoms
// reference).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpmx/particles/atoms.hpp"

namespace mpmx::dpd {

inline constexpr int kMobile = -1;

struct Particles : particles::Atoms {
  std::vector<double> mass;  // amu
  std::vector<double> u;     // internal energy, eV (DPDE; 0 in isothermal DPD)
  std::vector<int> group;    // rigid group index, or kMobile

  void resize(std::size_t n);
  void push_back(double px, double py, double pz, double m, int t, std::int64_t ident);
  // Reorders every field by `order` (new index k takes old index order[k]).
  void permute(const std::vector<std::size_t>& order);
  bool rigid(std::size_t i) const { return group[i] != kMobile; }
};

}  // namespace mpmx::dpd
