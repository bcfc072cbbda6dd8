#pragma once
// dpd::System: a set of DPD(E) mesoparticles (seed 004 eqs. 2.2-2.5) in a domain with
// periodic or open axes, advanced by one of two integrators:
//
//  - Shardlow splitting (the reference, as LAMMPS's DPD-REACT `fix shardlow` + `fix
//    nve`): per step, the stochastic/dissipative pair sweep over dt (shardlow.hpp),
//    then velocity Verlet with the conservative forces. DPDE or isothermal DPD.
//  - velocity Verlet with the conservative, dissipative and random pair forces
//    together (isothermal DPD, LAMMPS `pair dpd` + `fix nve`), the dissipative force
//    taken at the half-step velocities.
//
// Rigid groups (the seed's flyer and tensile grips) move at their set velocity; their
// forces are computed (the grips' force gives the tensile stress) but not integrated.
//
//   dpd::System s(particles, domain, potential, params, options, groups);
//   s.advance(1000, 0.001);          // steps of dt (ps)
//   s.total_energy();                // kinetic + conservative + internal (eV)
//
// Between calls the velocities and forces belong to the stored positions.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "mpmx/dpd/domain.hpp"
#include "mpmx/dpd/forces.hpp"
#include "mpmx/dpd/mover.hpp"
#include "mpmx/dpd/pair_list.hpp"
#include "mpmx/dpd/particles.hpp"
#include "mpmx/dpd/potential/registry.hpp"
#include "mpmx/dpd/shardlow.hpp"
#include "mpmx/dpd/thermostat.hpp"
#include "mpmx/particles/box.hpp"

namespace mpmx::dpd {

enum class Integrator { shardlow, velocity_verlet };

struct DpdParams {
  bool energy_conserving = false;  // DPDE (internal energies, T_ij from them) or isothermal DPD
  Integrator integrator = Integrator::shardlow;
  double gamma = 0;          // amu/ps (seed: 0.2)
  double cutoff = 1;         // rc_d of the weight functions, Angstrom
  double temperature = 0;    // K, isothermal DPD's bath
  double heat_capacity = 0;  // C_v per particle, eV/K (DPDE)
  std::uint64_t seed = 1;
};

struct SystemOptions {
  double skin = 1.0;  // Angstrom
  int threads = 1;
  bool sort = true;   // spatial sort at each neighbour rebuild (deterministic)
  int tile_particles = 0;  // particles per tile of the pair forces; 0: from the count
};

struct RigidGroup {
  std::string name;
  particles::Vec3 velocity{};  // Angstrom/ps
  // Moved by the mover (the MPM points of a concurrent run), not at a set velocity; they
  // take part in the pair forces with the other particles (not among themselves) and,
  // as particles of infinite mass, in the sweep.
  bool external = false;
  // A rigid body with an initial velocity (the seed's flyer): its velocity follows the
  // total pair force on it over its mass; otherwise it moves at the set velocity.
  bool free = false;
  double mass = 0;  // amu, set when the group is freed
};

class System {
 public:
  System(Particles particles, Domain domain, PairPotential potential, DpdParams params, SystemOptions options = {},
         std::vector<RigidGroup> groups = {});

  // nsteps steps of dt (ps); with a thermostat, Berendsen after every step.
  void advance(int nsteps, double dt, const Berendsen* thermostat = nullptr);
  // From now on `mover` (not owned; null: velocity Verlet again) moves the particles
  // after the sweep, from the forces at the step's start.
  void set_mover(Mover* mover) { mover_ = mover; }

  double potential_energy() const { return sums_.energy; }  // eV, conservative (valid from construction)
  double kinetic_energy() const;                            // eV, every particle
  double internal_energy() const;                           // eV, sum of u_i
  double total_energy() const { return kinetic_energy() + potential_energy() + internal_energy(); }
  double temperature() const { return kinetic_temperature(p_); }  // K, mobile, 3N-3
  double internal_temperature() const;                      // K, mean u_i / C_v (DPDE)
  particles::Vec3 momentum() const;                                // amu Angstrom/ps
  const particles::Sym6& virial() const { return sums_.virial; }   // eV: sum over pairs r_a F_b
  // Cauchy stress of the domain's volume, kinetic + virial, compression negative (GPa).
  particles::Mat3 stress_gpa() const;
  double pressure_gpa() const;
  // Sum of the pair forces on a rigid group's particles (eV/Angstrom).
  particles::Vec3 group_force(int group) const;

  const Particles& particles() const { return p_; }
  // Mutable access: neighbours and forces are rebuilt before the next use.
  Particles& edit_particles() {
    valid_ = false;
    return p_;
  }
  const Domain& domain() const { return d_; }
  const PairPotential& potential() const { return pot_; }
  const DpdParams& params() const { return par_; }
  const SystemOptions& options() const { return opt_; }
  const std::vector<RigidGroup>& groups() const { return groups_; }
  // The index of the group called `name`, or -1.
  int group_index(std::string_view name) const;
  void set_threads(int n) { opt_.threads = n; }
  // Sets a rigid group's velocity (its particles take it at once).
  void set_group_velocity(int group, const particles::Vec3& v);
  // From now on rigid group g moves as a free rigid body (translation) from its velocity.
  void release_group(int g);
  // Moves the mobile particles of `ids` into the external group `group` (at rest).
  void make_external(int group, const std::vector<std::int64_t>& ids);
  std::int64_t step() const { return step_; }
  double time() const { return time_; }
  std::int64_t neighbor_builds() const { return list_.nb.builds; }
  int sweep_slabs() const { return list_.slabs(); }
  // Neighbour list and forces for the current state.
  void refresh(double dt);

  // Checkpoint (dpd/checkpoint.cpp): the whole state (particles with their forces, the
  // groups' motion, step, time, the tallies, the neighbour list's build positions) in a
  // portable binary form. load() replaces the state of a system built from the same deck
  // (the same particles and groups, in any order) and continues bit-for-bit: the list is
  // rebuilt from the positions it was built from. The random forces need no state: they
  // are drawn from (seed, step, pair). Throws InputError for a state that does not fit.
  void save(std::ostream& out) const;
  void load(std::istream& in);

 private:
  void rebuild();
  void mark_external();
  void compute_forces(double dt, bool tally = true);
  void check_finite() const;
  void kick_free_groups(double dt);
  double neighbor_cutoff() const;

  Particles p_;
  Domain d_;
  PairPotential pot_;
  DpdParams par_;
  SystemOptions opt_;
  std::vector<RigidGroup> groups_;
  PairList list_;
  ForceBuffers buf_;
  SweepWork sweep_work_;
  particles::ForceSums sums_;
  std::int64_t step_ = 0;
  double time_ = 0;
  double dt_ = 0;  // the step the stored forces were computed for (random force ~ 1/sqrt(dt))
  bool valid_ = false;
  Mover* mover_ = nullptr;
  std::vector<std::uint8_t> no_pair_;  // per particle: in an external group (empty: none is)
};

}  // namespace mpmx::dpd
