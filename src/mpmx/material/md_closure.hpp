#pragma once
// md_closure: the heterogeneous multiscale closure of chapter 6. Every material point
// owns a periodic MD box (section 6.2): fcc at the potential's least-energy lattice
// constant, n x n x n cells, the point's initial engineering strain along x, atoms at
// twice the point's temperature, relaxed at zero strain rate. It is built once and
// never re-initialised; each continuum step its velocity gradient (eq. 6.3) deforms
// the box for dt / dt_md MD steps and the box's virial stress (eq. 2.25) is the point's
// stress. Units are converted here only (core/units).
#include <cstdint>
#include <vector>

#include "mpmx/core/units.hpp"
#include "mpmx/material/material.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/multiscale/batch.hpp"

namespace mpmx::material {

struct MdClosureConfig {
  md::PotentialSpec potential;
  int cells = 4;                   // n x n x n fcc cells: 4 -> 256 atoms, 5 -> 500
  double temperature = 0.0;        // K
  std::uint64_t seed = 1;          // with the point index: one random stream per point
  double dt = 0.001;               // MD step, ps
  std::int64_t relax_steps = 0;    // zero-strain-rate relaxation after the thermal start
  multiscale::StressSample sample = multiscale::StressSample::last;
  double skin = 1.0;               // Angstrom
  bool mixed_precision = false;
  units::UnitSystem units{"nm_ps_GPa", 10.0, 1.0, 1.0};
  int threads = 0;                 // 0: OpenMP default

  int atoms_per_point() const { return 4 * cells * cells * cells; }
  // MD steps in a continuum step `dt` (continuum units); 0 when not a whole number.
  int md_steps(double dt) const;
};

// The least-energy lattice, C11 and density of a closure's potential, in continuum
// units, without building any box (deck checks: CFL limit, the density of the points).
struct MdClosureProperties {
  md::FccEquilibrium equilibrium;
  double density = 0.0, modulus = 0.0, sound_speed = 0.0;
};
MdClosureProperties md_closure_properties(const md::PotentialSpec& potential, const units::UnitSystem& u);

class MdClosure final : public Material<1> {
 public:
  explicit MdClosure(const MdClosureConfig& config);

  std::string name() const override { return "md_closure"; }
  // Builds one box per point from p.strain (engineering, along x); sets the stress.
  void initialize(const Points<1>& p) override;
  void update_stress(const Points<1>& p, double dt) override;
  // sqrt(C11 / rho): the 0 K uniaxial-strain wave speed, for the viscosity.
  double sound_speed(const Points<1>& p, std::size_t q) const override;
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;
  long long state_points() const override { return static_cast<long long>(boxes_.size()); }

  const md::FccEquilibrium& equilibrium() const { return props_.equilibrium; }
  double density() const { return props_.density; }  // unstrained crystal, continuum units
  double modulus() const { return props_.modulus; }  // C11, continuum units
  int atoms_per_point() const { return cfg_.atoms_per_point(); }
  std::int64_t atom_steps() const { return atom_steps_; }
  int threads() const { return batch_.threads(); }
  // The run's --threads (0: OpenMP's default); set before initialize().
  void set_threads(int threads) { batch_ = multiscale::Batch(threads); }
  const std::vector<md::System>& boxes() const { return boxes_; }

 private:
  md::SystemOptions box_options() const;

  MdClosureConfig cfg_;
  md::Potential pot_;
  MdClosureProperties props_;
  multiscale::Batch batch_;
  std::vector<md::System> boxes_;
  std::vector<md::Mat3> gradients_, stress_;
  std::int64_t atom_steps_ = 0;
};

}  // namespace mpmx::material
