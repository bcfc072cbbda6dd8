#pragma once
// Direct MD of the copper jet (dissertation sec. 7.1): a crystal block (fcc along the
// axes, or any lattice and orientation of particles/oriented_lattice.hpp, counted in its
// periodic tiles), the first `piston_cells` tiles of it a rigid piston held at rest, an
// isosceles V notch cut into the right face across the whole y period, the rest sent at
// -up into the piston (the momentum mirror), free in x (vacuum beyond both faces),
// periodic in y and z. Reduced scale s: the x and y tile counts, the notch depth and the
// run's times are multiplied by s; z keeps its tile count.
#include <array>
#include <cstdint>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

struct JetConfig {
  double scale = 1.0;
  std::array<int, 3> cells{400, 200, 10};  // tiles at scale 1 (x includes the piston); z not scaled
  int piston_cells = 40;                   // tiles at scale 1
  double notch_depth_nm = 36.0;            // at scale 1
  double velocity_km_s = 2.5;              // the block's speed toward the piston (up)
  double lattice_constant = 3.615;
  particles::LatticeSpec lattice;          // type and orient (one element); its constant is lattice_constant
  double temperature = 0.0;                // K target; atoms start at twice it (sec. 7.1)
  std::uint64_t seed = 1;

  // The scaled sizes.
  int nx() const;
  int ny() const;
  int nz() const { return cells[2]; }
  int npiston() const;
  double notch_depth_A() const { return notch_depth_nm * 10.0 * scale; }
};

struct JetGeometry {
  double x0 = 0;          // the piston's left face (Angstrom)
  double length = 0;      // x extent of the sample, nx tiles (Angstrom)
  double piston_face = 0; // x of the piston's right face, between its last plane and the block's first
  double notch_tip = 0;   // x of the notch tip at t = 0
  double ly = 0, lz = 0;
  std::int64_t piston_atoms = 0;  // ids 1..piston_atoms
  particles::LatticeSpec lattice;  // the crystal cut (its constant set)
  Vec3 origin{};                   // box position of the crystal's site at its origin
};

// The faces lie half way between atomic planes: the piston's left face and the block's
// right one half the tile's end gap (particles/tile_planes.hpp) beyond the outer planes,
// and the atoms sit that half gap in from y = 0 and z = 0, off the bins' edges.
// The sample at t = 0: piston atoms first (ids 1..piston_atoms, held at rest), block
// atoms thermalised at twice the temperature about zero mean, then given -up along x.
// Box: x periodic with a vacuum wider than 2 (cutoff + skin) plus half the sample
// (room for the jet), so no pair crosses it. Needs options.per_atom for the bins.
System build_jet(const JetConfig& c, Potential potential, SystemOptions options, JetGeometry* geometry);

}  // namespace mpmx::md
