#pragma once
// All-atom MD of seed 004's flyer-on-target rod (sec. 4.1.1): a rigid flyer, then the
// target continuing its lattice along x (fcc cells along the axes, or the periodic tiles
// of any one-element lattice and orientation of particles/oriented_lattice.hpp), both with the same y-z cross-section, open on
// every side (vacuum around the sample in the periodic box, wider than twice the pair reach,
// so no pair crosses it). The DPD rod's all-atom reference: 8 atoms per mesoparticle.
//
// The deck's frame is the DPD deck's: the flyer's first plane at x = 0, its last tile ending
// where the target's first plane sits (x = flyer_cells tile lengths), the sample's corner
// at y = z = 0.
// The box holds the sample shifted by `offset` along each axis.
#include <array>
#include <cstdint>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

struct RodConfig {
  double lattice_constant = 3.6414;          // Angstrom (the crystal's zero-pressure constant at the temperature)
  particles::LatticeSpec lattice;            // type and orient (one element); its constant is lattice_constant
  std::array<int, 3> target_cells{60, 20, 20};  // tiles of `lattice` (fcc along the axes: cubic cells)
  int flyer_cells = 4;                       // tiles along x; the target's y and z tiles
  double temperature = 0;                    // K target; the target's atoms start at twice it (sec. 6.2)
  std::uint64_t seed = 1;
};

struct RodGeometry {
  Vec3 offset{};                 // box position = deck position + offset
  double impact_face = 0;        // deck x of the target's first plane
  double length = 0;             // target length along x (tiles x tile length)
  double ly = 0, lz = 0;         // cross-section
  std::int64_t flyer_atoms = 0;  // ids 1..flyer_atoms
};

// The sample at t = 0: flyer atoms first (ids 1..flyer_atoms), held at rest as a rigid body
// (System::set_frozen_ids; System::release_rigid sends it); the target's atoms thermalised
// at twice the temperature about zero mean momentum. x room for the rod's drift after the
// impact: half the sample's length beyond each face.
System build_rod(const RodConfig& c, Potential potential, SystemOptions options, RodGeometry* geometry);

}  // namespace mpmx::md
