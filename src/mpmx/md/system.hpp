#pragma once
// md::System: one self-contained periodic MD box, the unit the multiscale method keeps
// in every material point (section 6.2). It owns its atoms, box, neighbour list, force
// buffers and random stream; the potential is shared and immutable, so a System is
// cheap to copy and many can advance independently on different threads.
//
//   System s(crystal.atoms, crystal.box, potential);
//   s.thermalize(300.0, seed, point_id);          // section 6.2, Maxwell at 2T
//   s.advance(n, velocity_gradient, dt);          // eqs. 5.3-5.8, 5.20
//   Mat3 sigma = s.stress_gpa();                  // eq. 2.25, Cauchy, GPa
//
// Between calls the stored velocities are on-step velocities (eq. 5.6) and the forces
// belong to the stored positions.
#include <cstdint>
#include <iosfwd>
#include <vector>

#include "mpmx/md/forces.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/potential/potential.hpp"

namespace mpmx::md {

enum class Deformation {
  boundary,  // seed's scheme: the box deforms, atoms feel it through the images (eq. 5.8)
  affine,    // atoms also follow the streaming motion G x (velocities are peculiar)
};

// Reflecting walls normal to x (direct-MD bars): an atom beyond a wall is mirrored,
// x -> 2 w - x, v_x -> 2 v_w - v_x (a fixed wall for v_w = 0, a moving or
// momentum-mirror piston otherwise); the walls move with v_w.
struct Walls {
  bool enabled = false;
  double lo = 0, hi = 0;      // Angstrom
  double v_lo = 0, v_hi = 0;  // Angstrom/ps
};

struct SystemOptions {
  double skin = 1.0;                       // Angstrom
  Deformation deformation = Deformation::boundary;
  bool mixed_precision = false;            // float pair arithmetic, double sums
  bool sort_atoms = true;                  // spatial sort at each neighbour rebuild
  bool per_atom = false;                   // keep per-atom energy and virial (binned stress)
  // One large system (direct MD): neighbour list, forces and integration spread over
  // `threads` threads, each atom summing its pairs in a fixed order, so any count gives
  // the same bits. Off for the many small boxes of a multiscale run (one thread each,
  // the scattering force loop: faster there).
  bool threaded = false;
  int threads = 1;     // used when threaded
  int tile_atoms = 0;  // atoms per tile of the threaded form; 0: chosen from the atom count
};

class System {
 public:
  System(Atoms atoms, Box box, Potential potential, SystemOptions options = {});
  System(const Crystal& crystal, Potential potential, SystemOptions options = {})
      : System(crystal.atoms, crystal.box, std::move(potential), options) {}

  // Section 6.2: Maxwell speeds at twice `target_K`, isotropic directions, zero total
  // momentum, from the stream (seed, stream_id) - the same on any thread count.
  void thermalize(double target_K, std::uint64_t seed, std::uint64_t stream_id);
  // Velocities of the atoms with id > after_id scaled about their mean so that their
  // kinetic temperature (3N-3 degrees of freedom) is `target_K` (an equilibration's
  // rescaling, leaving a rigid body's atoms, ids 1..after_id, alone). Forces stay valid.
  void rescale_temperature(double target_K, std::int64_t after_id = 0);
  // The kinetic temperature of the atoms with id > after_id about their mean velocity
  // (3N-3 degrees of freedom; 0 for fewer than two atoms).
  double temperature_after(std::int64_t after_id) const;
  // Eq. 7.11 hook: adds `energy_eV` to the box as kinetic energy about the mean velocity.
  void add_energy(double energy_eV);
  // Adds the streaming velocity G (x - box centre) of a homogeneous deformation (G made
  // upper triangular by eq. 5.20), so the box starts deforming as a continuum would.
  void add_streaming_velocity(const Mat3& velocity_gradient);

  // Advances n leapfrog steps of dt (ps) under the velocity gradient (1/ps, row-major
  // dv_i/dx_j); a gradient with a lower triangle is made upper triangular by eq. 5.20.
  void advance(int nsteps, const Mat3& velocity_gradient, double dt);
  void advance(int nsteps, double dt) { advance(nsteps, Mat3{}, dt); }

  // An extended system around the velocity-Verlet step (md/nose_hoover.hpp): `initial`
  // sees the on-step velocities, forces and virial before the first half kick, `remap`
  // runs before and after the drift (a barostat's half-step dilation), `final` after the
  // closing half kick.
  class Coupling {
   public:
    virtual ~Coupling() = default;
    virtual void initial(System& s, double dt) = 0;
    virtual void remap(System& s, double dt) = 0;
    virtual void final(System& s, double dt) = 0;
  };
  // Advances n steps of dt (ps) coupled to `c`, with the energy and virial every step (a
  // barostat reads the pressure at each). An orthogonal box, no velocity gradient.
  void advance_coupled(int nsteps, double dt, Coupling& c);
  // A coupling's moves: every velocity component times f along its axis (a thermostat's
  // scaling, about zero as LAMMPS's fix nh); the box's edges and the atoms' positions
  // times f along each axis (a barostat's dilation; forces recomputed by the step).
  void scale_velocities(const Vec3& f);
  void dilate(const Vec3& f);
  // Sum of m v_a v_a per axis (eV, on-step velocities about zero): the kinetic part of a
  // barostat's per-axis pressure.
  Vec3 mvv() const;

  // Eq. 2.25 for the whole box, Cauchy sign (compression negative).
  Mat3 stress() const;      // eV/Angstrom^3
  Mat3 stress_gpa() const;  // GPa
  // Binned (needs options.per_atom): slabs along x, columns over x-y.
  std::vector<Mat3> slab_stress_gpa(int nbins) const;
  std::vector<Mat3> column_stress_gpa(int nx, int ny) const;

  double potential_energy() const { return sums_.energy; }  // eV, total
  double kinetic_energy() const;                            // eV, total, on-step velocities
  double thermal_kinetic_energy() const;                    // eV, about the mean velocity
  double temperature() const;                               // K, 3N-3 degrees of freedom
  const Sym6& virial() const { return sums_.virial; }       // eV (pair virial sum)
  // Per-atom virial (6 per atom, half of each pair), kept when options.per_atom (summed
  // at the last step of an advance, as the energy and virial are).
  const std::vector<double>& per_atom_virial() const { return work_.virial_atom; }
  // Per-atom potential energy (eV; F(rho_i) and half of each pair), kept likewise.
  const std::vector<double>& per_atom_energy() const { return work_.energy_atom; }
  // Each atom's stress in GPa (stress.hpp, atom_stress), 6 per atom; needs options.per_atom.
  std::vector<double> atom_stress_gpa() const;

  const Atoms& atoms() const { return atoms_; }
  // Mutable access: forces are recomputed before the next use.
  Atoms& edit_atoms() {
    valid_ = false;
    return atoms_;
  }
  const Box& box() const { return box_; }
  void set_box(const Box& b) {
    box_ = b;
    valid_ = false;
  }
  const Potential& potential() const { return pot_; }
  const std::vector<double>& type_mass() const { return mass_; }
  const SystemOptions& options() const { return opt_; }
  std::int64_t step() const { return step_; }
  double time() const { return time_; }
  std::int64_t neighbor_builds() const { return builds_ + nb_.builds; }
  const Mat3& gradient() const { return g_; }
  void set_walls(const Walls& w) { walls_ = w; }
  // Atoms with id <= max_id are held at rest (a rigid piston, sec. 7.1): their
  // velocities are zeroed after every kick, so they never move; their forces still
  // count in the virial. 0: none.
  void set_frozen_ids(std::int64_t max_id);
  // From now on those atoms (set_frozen_ids) are a free rigid body (seed 004's flyer): they
  // take `velocity` (Angstrom/ps) now, and after every kick the body's mean velocity, so it
  // translates as one under the total force on it (internal forces cancel).
  void release_rigid(const Vec3& velocity);
  // The rigid atoms (ids 1..max_id) and whether they are free, set without touching the
  // velocities (a checkpoint's state is already the body's).
  void set_rigid(std::int64_t max_id, bool free) {
    frozen_ids_ = max_id;
    rigid_free_ = free;
  }
  std::int64_t frozen_ids() const { return frozen_ids_; }
  bool rigid_free() const { return rigid_free_; }
  const Walls& walls() const { return walls_; }
  // Forces for the current state (recomputed if atoms or box were edited).
  void refresh();
  // Keeps only what the next advance needs (atoms with their forces, box, stream,
  // tallies, and the neighbour list with what decides its rebuild: Neighbors::shed); the
  // force buffers and packed positions are freed. The multiscale boxes between macro
  // steps: the list lives on and is rebuilt by the skin, not by the macro step.
  void compact();
  // Bytes this box holds now (its arrays' capacity).
  std::size_t bytes() const;

  // Atoms with positions in the fundamental box and the velocities of those images.
  Atoms snapshot() const;

  // Checkpoint: the whole state in a portable binary form (bit-for-bit restart).
  void save(std::ostream& out) const;
  static System load(std::istream& in, Potential potential, SystemOptions options = {});

 private:
  void rebuild();
  void compute_forces(bool tally = true);
  void check_finite() const;
  void reflect(double dt);
  void hold_frozen();

  Atoms atoms_;
  Box box_;
  Potential pot_;
  SystemOptions opt_;
  std::vector<double> mass_;
  Neighbors nb_;
  ForceWork work_;
  ForceSums sums_;
  RngStream rng_;
  Mat3 g_{};
  Walls walls_;
  std::int64_t frozen_ids_ = 0;
  bool rigid_free_ = false;
  std::int64_t step_ = 0;
  double time_ = 0;
  std::int64_t builds_ = 0;  // neighbour-list builds before a list-less checkpoint
  bool valid_ = false;
};

}  // namespace mpmx::md
