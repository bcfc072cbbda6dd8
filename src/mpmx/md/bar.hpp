#pragma once
// Direct MD of a bar (the reference of chapter 6): a crystal bar along x (fcc along the
// cube axes, or any lattice and orientation of particles/oriented_lattice.hpp) between reflecting
// walls (the left one optionally a moving piston), periodic in y and z, with an initial
// engineering strain on its left part, and the stress of eq. 2.25 in slabs along x.
#include <vector>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::md {

struct BarConfig {
  int cells_x = 40, cells_yz = 4;  // periodic tiles of `lattice` (fcc along the axes: cubic cells)
  double lattice_constant = 3.615;
  particles::LatticeSpec lattice;  // type and orient; its constant is lattice_constant
  double strain_left = 0.0;       // engineering strain of the part x < split (negative: compressed)
  double split = 0.5;             // fraction of the bar that is strained
  double temperature = 0.0;       // K target (atoms start at twice it, section 6.2)
  std::uint64_t seed = 1;
  double piston_velocity = 0.0;   // Angstrom/ps of the left wall (0: fixed reflecting wall)
  int bins = 100;
};

class Bar {
 public:
  Bar(const BarConfig& config, Potential potential, SystemOptions options = {});

  void advance(int nsteps, double dt) { sys_.advance(nsteps, dt); }
  // Slab stress (GPa) over the bar between the walls, `bins` slabs.
  std::vector<Mat3> slab_stress_gpa() const;
  // x of each slab centre (Angstrom).
  std::vector<double> slab_centres() const;
  const System& system() const { return sys_; }
  System& system() { return sys_; }

 private:
  static System build(const BarConfig& c, Potential p, SystemOptions o);
  BarConfig cfg_;
  System sys_;
};

}  // namespace mpmx::md
