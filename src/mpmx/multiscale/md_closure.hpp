#pragma once
// md_closure: the heterogeneous multiscale closure of chapter 6. Every material point
// takes its stress from a periodic MD box (section 6.2): fcc at the potential's least-energy lattice
// constant, n x n x n cells, the point's initial engineering strain along x, atoms at
// twice the point's temperature, relaxed at zero strain rate. It is built once and
// never re-initialised; each continuum step its velocity gradient (eq. 6.3) deforms
// the box for dt / dt_md MD steps and the box's virial stress (eq. 2.25) is the point's
// stress. Units are converted here only (core/units).
// The crystal is any of particles/oriented_lattice's (fcc, bcc, hcp in any orientation;
// `cells` periodic tiles per axis, fcc along the axes as it always was), at the 0 K
// lattice constant or, with `prepare = npt`, at the mean lattice constant of one box
// relaxed by NPT at the deck's temperature and zero pressure before any point's box is built.
//
// Points whose boxes follow one history share one box (multiscale/box_groups.hpp: a
// group is cloned when a member's history departs, a few members are audited on private
// boxes). Under MPI each rank builds and advances the boxes of its groups; every rank then
// holds every group's result (stress and box) and the continuum step is replicated on
// all ranks. Replicated rather than run on rank 0:
// the continuum costs nothing beside the MD, every rank then takes the same decisions
// from the same state (records, the CFL step, the checks) without a protocol of
// commands, and the gradients need no scatter. A box's state and random stream depend
// only on its group's first point, so the results do not depend on the ranks or threads.
// A box keeps its pair structure between macro steps (md::System::compact frees only the
// force buffers and packed positions): its neighbour list is rebuilt by the skin
// criterion, not by the macro step, which at s = 0.1 holds only 10 MD steps.
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <memory>
#include <cmath>
#include <optional>
#include <vector>

#include "mpmx/core/ranks.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/material/material.hpp"
#include "mpmx/md/compression_moduli.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/multiscale/batch.hpp"
#include "mpmx/multiscale/box_groups.hpp"
#include "mpmx/multiscale/spread.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::multiscale {

using material::Material;
using material::Points;

// How the boxes' lattice constant is chosen: the 0 K crystal's, or NPT's at the temperature.
enum class BoxPrepare { lattice, npt };

// What the NPT preparation found (prepare_npt below).
struct PreparedLattice {
  double lattice_constant = 0.0;  // Angstrom
  double pressure_gpa = 0.0;      // the mean pressure over the second half
  double temperature = 0.0;       // the mean temperature over the second half, K
};

struct MdClosureConfig {
  md::PotentialSpec potential;
  particles::LatticeSpec lattice;  // style, orientation, c/a (its constant is not read)
  int cells = 4;                   // n x n x n tiles: fcc along the axes, 4 -> 256 atoms, 5 -> 500
  BoxPrepare prepare = BoxPrepare::lattice;
  std::int64_t prepare_steps = 10000;  // prepare = npt: the NPT run's steps
  // prepare = npt: its result when the deck's reading found it (the points' density is
  // then the prepared crystal's); without it initialize() runs the preparation itself.
  std::optional<PreparedLattice> prepared;
  double temperature = 0.0;        // K
  std::uint64_t seed = 1;          // with a group's first point: one random stream per box
  double dt = 0.001;               // MD step, ps
  std::int64_t relax_steps = 0;    // zero-strain-rate relaxation after the thermal start
  multiscale::StressSample sample = multiscale::StressSample::last;
  double skin = 1.0;               // Angstrom
  bool mixed_precision = false;
  // How a box follows its gradient (md/system.hpp): the seed's boundary scheme (the images
  // move, the atoms feel it through the faces) or affine (every atom's position remapped
  // each step). At the jet's front rates the boundary scheme shocks the box from its faces.
  md::Deformation deformation = md::Deformation::boundary;
  units::UnitSystem units{"nm_ps_GPa", 10.0, 1.0, 1.0};
  int threads = 0;                 // 0: OpenMP default
  int energy_consistency = -1;     // eq. 7.11: 1 on, 0 off, -1 the default (on in 2-D and 3-D)
  ShareOptions share;              // [material.md.share]: boxes shared by history
  // The 0 K crystal's tangent moduli against its compression (md/compression_moduli.hpp),
  // the points' stiffness for the stable step; made by the deck's reading, else by the law.
  std::shared_ptr<const md::CompressionModuli> stiffness;

  // The atoms of one tile times cells^3 (4 cells^3 for fcc along the axes).
  int atoms_per_point() const;
  // MD steps in a continuum step `dt` (continuum units); 0 when not a whole number.
  int md_steps(double dt) const;
};

// The least-energy lattice, C11 and density of a closure's potential, in continuum
// units, without building any box (deck checks: CFL limit, the density of the points).
struct MdClosureProperties {
  md::FccEquilibrium equilibrium;
  double density = 0.0, modulus = 0.0, sound_speed = 0.0;
  double c12 = 0.0, c44 = 0.0;  // the other cubic constants (continuum units)
  double cutoff = 0.0;          // the potential's, Angstrom
};
// Of fcc along the axes unless `lattice` names another crystal (its box-frame constants).
// The compression table (md/compression_moduli.hpp) of the same crystal at its 0 K constant.
std::shared_ptr<const md::CompressionModuli> md_closure_stiffness(const md::Potential& pot,
                                                                  const particles::LatticeSpec& lattice,
                                                                  double a0);
MdClosureProperties md_closure_properties(const md::PotentialSpec& potential, const units::UnitSystem& u,
                                          const particles::LatticeSpec& lattice = {});

// The NPT preparation (prepare = npt): one box of `cells`^3 tiles of the crystal at the
// 0 K constant a0, its atoms at `temperature` (stream `seed`), run by the Nose-Hoover
// chain and the isotropic MTK barostat (target 0 GPa, Tdamp 0.1 ps, Pdamp 1 ps) for
// `steps`; the lattice constant of its mean volume over the second half. Interrupted
// (Ctrl-C), it returns a0 at once: the caller ends the run.
PreparedLattice prepare_npt(const md::Potential& pot, const MdClosureConfig& c, double a0);

// In 2-D and 3-D the point's full velocity gradient drives its box (eqs. 5.7-5.8; a lower
// triangle is turned upper triangular by eq. 5.20, the z length of a 2-D run stays
// fixed) and the full virial stress comes back. Eq. 5.20 gives the box the same rate of
// deformation but another spin than the point's, so each point carries the rotation R
// between the box's crystal and the point's (dR/dt = W R - R W') and returns R sigma R^T.
// Energy consistency (eq. 7.11, on by default in 2-D and 3-D): each macro step the
// difference between the continuum's work V sigma : D dt (its members' mean) and the
// box's own energy change goes into the box as kinetic energy about its mean velocity.
template <int Dim>
class MdClosure final : public Material<Dim>, public material::Subscale {
 public:
  explicit MdClosure(const MdClosureConfig& config);

  std::string name() const override { return "md_closure"; }
  // Builds one box per group of points that start alike (p.strain: engineering, along
  // x), relaxed once; sets every point's stress. Collective under MPI, as are
  // update_stress, save and load; a failure on any rank throws the same RunError on
  // every rank.
  void initialize(const Points<Dim>& p) override;
  void update_stress(const Points<Dim>& p, double dt) override;
  // The boxes' kinetic temperature (K, about their mean velocity) at every point; in 1-D
  // also the boxes' sigma_yy and sigma_zz.
  std::vector<material::PointField> point_fields(const Points<Dim>& p) const override;
  // Point q's box (its group's) as a LAMMPS dump frame at `step`.
  // Its group's box as a LAMMPS dump frame; `fields` (md/lammps_dump.hpp: pe, stress,
  // structure) are evaluated on a copy of the box, so the run's own box is not touched.
  std::string point_model_dump(std::size_t q, std::int64_t step, const std::vector<std::string>& fields) const override;
  bool runs_point_model(std::size_t) const override { return true; }
  // sqrt(C11 / rho): the 0 K uniaxial-strain wave speed, for the viscosity.
  double sound_speed(const Points<Dim>& p, std::size_t q) const override;
  // sqrt(M(J) / rho) for the stable step: M the crystal's largest tangent modulus at the
  // point's J (the 0 K crystal's density over its own), never below C11.
  double signal_speed(const Points<Dim>& p, std::size_t q) const override;
  // The groups and every rank's boxes in group order, written by rank 0 alone: the file
  // is the single-process one. load keeps this rank's share, so any rank count resumes it.
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;
  // Moves boxes between ranks so that each rank's measured cost is about equal.
  bool rebalance(double threshold) override;
  long long state_points() const override { return static_cast<long long>(groups_.points()); }

  const md::FccEquilibrium& equilibrium() const { return props_.equilibrium; }
  // The lattice constant the boxes are built at (the 0 K one, or NPT's), Angstrom.
  double box_lattice_constant() const {
    return prepared_ ? prepared_->lattice_constant : props_.equilibrium.lattice_constant;
  }
  // The unstrained boxes' crystal (prepared by NPT or at 0 K), continuum units.
  double density() const {
    return props_.density * std::pow(props_.equilibrium.lattice_constant / box_lattice_constant(), 3);
  }
  double modulus() const { return props_.modulus; }  // C11, continuum units
  int atoms_per_point() const { return cfg_.atoms_per_point(); }
  std::int64_t atom_steps() const { return atom_steps_; }  // all ranks' boxes, audits included
  std::int64_t atom_steps_unshared() const { return atom_steps_unshared_; }  // one box per point
  double md_seconds() const { return md_seconds_; }        // wall time in this rank's boxes
  int threads() const override { return batch_.threads(); }
  // The boxes spread over the run's --threads (0: OpenMP's default), set before
  // initialize(); the continuum's particle threads (set_threads) do not apply to them.
  void use_run_threads(int threads) override { batch_ = multiscale::Batch(threads); }
  void set_threads(int) override {}
  // What the run record shows of the boxes (material::Subscale).
  const material::Subscale* subscale() const override { return this; }
  std::int64_t steps() const override { return atom_steps_; }
  double seconds() const override { return md_seconds_; }
  std::vector<material::Figure> figures() const override;

  const BoxGroups& groups() const { return groups_; }
  // Group g's box, where this rank runs it (null elsewhere).
  const md::System* box(std::size_t g) const { return g < boxes_.size() ? boxes_[g].get() : nullptr; }
  // Eq. 7.11: energy put into (positive) or taken from the boxes so far, eV, all ranks;
  // and what could not be taken from a box with too little thermal energy.
  double energy_injected_ev() const { return injected_ev_; }
  // What the boxes still owe of eq. 7.11's removals (eV, >= 0): carried, not lost.
  // (A merge by state may owe a box energy too, put in at its next step: not counted.)
  double energy_shortfall_ev() const {
    return -std::accumulate(owed_.begin(), owed_.end(), 0.0, [](double s, double o) { return s + std::min(o, 0.0); });
  }
  // Neighbour-list builds of every box since it was made (all ranks, at the last step).
  std::int64_t neighbor_builds() const { return neighbor_builds_; }
  // The audit: the auditors' private stress against their groups', relative RMS over
  // the run and the largest difference of a component (GPa); NaN before any.
  double audit_rel_rms() const;
  double audit_max_gpa() const { return audit_samples_ > 0 ? audit_max_gpa_ : std::nan(""); }
  // Merges by state: how many groups were absorbed, how many points moved with them, and
  // the absorbed boxes' stress against their survivors' at the merge (relative RMS, the
  // largest component difference in GPa).
  std::int64_t merges() const { return merges_; }
  std::int64_t merged_points() const { return merged_points_; }

 private:
  md::SystemOptions box_options() const;
  bool consistent() const { return cfg_.energy_consistency < 0 ? Dim > 1 : cfg_.energy_consistency == 1; }
  // The groups' boxes on the ranks: contiguous runs of groups of about equal cost.
  void spread_groups(const std::vector<double>& cost);
  bool mine(std::size_t g) const { return owner_[g] == ranks::rank(); }
  // New groups from a split (copies of their parents' boxes where this rank runs
  // them), new auditors' private boxes, dropped ones ended.
  void apply_split(const BoxGroups::Split& split);
  void start_audits(const std::vector<std::size_t>& points);
  // Step 5 (share.by_state): every group's box state, then the merge applied: the absorbed
  // boxes end, each survivor owes its box the energy that makes it its members' mean
  // (eq. 7.11's bookkeeping, carried into its next step), the per-group arrays compacted.
  std::vector<BoxState> box_states() const;
  void apply_merge(const BoxGroups::Merge& merge);
  // Advances group g's box (or auditor q's, with `audit`) by steps under gradient L;
  // returns what eq. 7.11 put in and could not take out.
  // Eq. 7.11's power on a box: the rate of deformation in the box's frame (1/ps), which
  // its own stress works against, and the viscous stresses' power (GPa/ps); a group's is
  // its members' mean.
  struct Power {
    md::Mat3 rate{};
    double viscous = 0.0;
  };
  std::pair<double, double> advance(md::System& box, const md::Mat3& L, const Power& power, int steps,
                                    md::Mat3& stress, double& owed);
  Power power_of(const Points<Dim>& p, std::size_t q) const;
  // Every rank's results into the groups and the points, after the ranks agree on the
  // first failure, if any.
  void publish(const Points<Dim>& p, std::optional<ranks::Failure> failed, bool strain, double dt,
               const std::vector<double>& injected, const std::vector<double>& short_of,
               const std::vector<std::array<double, 4>>& audit);
  void set_point_stress(const Points<Dim>& p, std::size_t q) const;
  void turn(const Points<Dim>& p, double dt_ps);

  MdClosureConfig cfg_;
  md::Potential pot_;
  MdClosureProperties props_;
  multiscale::Batch batch_;
  BoxGroups groups_;                                 // every rank
  std::vector<int> owner_;                           // the rank running each group
  std::vector<std::unique_ptr<md::System>> boxes_;   // by group; this rank's
  std::map<std::size_t, md::System> audits_;         // auditors' private boxes (this rank's groups), by point
  std::map<std::size_t, md::Mat3> audit_stress_;     // their last stress (box frame, GPa)
  std::vector<md::Mat3> stress_;                     // by group, box frame, GPa (every rank)
  std::vector<std::array<double, 7>> shape_;         // by group: lx, ly, lz, xy, xz, yz, neighbour builds
  std::vector<double> temperature_;                  // by group, K (every rank)
  std::vector<double> energy_;                       // by group, eV/amu, potential + thermal (every rank)
  // Eq. 7.11's removal a box could not take yet (eV, <= 0; by group, every rank; and by
  // auditor): carried into its next macro steps, never dropped (md_closure.cpp, advance).
  std::vector<double> owed_;
  std::map<std::size_t, double> audit_owed_;
  std::vector<md::Mat3> rotation_;                   // every point, on every rank
  std::vector<double> group_seconds_;                // each group's cost since the last rebalance check
  std::int64_t atom_steps_ = 0, atom_steps_unshared_ = 0;
  std::int64_t macro_step_ = 0;
  double md_seconds_ = 0.0;
  double injected_ev_ = 0.0;
  std::int64_t neighbor_builds_ = 0;
  double audit_d2_ = 0.0, audit_s2_ = 0.0, audit_max_gpa_ = 0.0;
  std::int64_t audit_samples_ = 0;
  std::int64_t merges_ = 0, merged_points_ = 0;
  double merge_d2_ = 0.0, merge_s2_ = 0.0, merge_max_gpa_ = 0.0;
  std::optional<PreparedLattice> prepared_;          // prepare = npt, from initialize (or the checkpoint)
  // MPMX_TEST_NAN_POINT: the point whose stress comes back NaN (tests only).
  std::optional<std::size_t> nan_point_;
};

}  // namespace mpmx::multiscale
