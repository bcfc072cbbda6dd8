#pragma once
// A constitutive closure works on the whole batch of material points at once, so that
// a costly closure (an MD system per point) can spread the batch over threads without
// the solver knowing. Called once per step, never per particle.
#include <cmath>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "mpmx/material/points.hpp"

namespace mpmx::material {

// A figure for the run record: a dotted key and its value.
using Figure = std::pair<std::string, std::variant<std::int64_t, double>>;

// What a law that runs a model of its own inside every point (md_closure: an MD box per
// point) reports of that work.
class Subscale {
 public:
  virtual ~Subscale() = default;
  virtual std::int64_t steps() const = 0;  // its steps in all (MD: atom-steps, every rank's)
  virtual double seconds() const = 0;      // wall time in it on this rank
  virtual int threads() const = 0;         // threads it spreads over
  virtual std::vector<Figure> figures() const = 0;
};

// The 1-D linear elastic law in the form the fused 1-D kernels (mpm/fused1d) take it;
// a law that has one supplies it (Material<1>::fused_elastic).
struct FusedElastic1d {
  double youngs_modulus = 0.0;
};

// A per-point quantity a law carries beyond the points' arrays, for the output (the MD
// boxes' temperature, the internal energy, the stress components a 1-D run keeps no
// array for): its name as the files write it, and one value per point.
struct PointField {
  std::string name;
  std::vector<double> values;
};

template <int Dim>
class Material {
 public:
  virtual ~Material() = default;
  virtual std::string name() const = 0;
  // Sets the initial stress (and any per-point state) from the initial fields: the
  // strain array for solids; for gases the caller has put -p0 on the stress diagonal.
  virtual void initialize(const Points<Dim>& p) = 0;
  // Stress at t^{n+1} from the velocity gradient grad_v (eq. 4.10) and the updated
  // volume; dt is the continuum step. A closure may keep per-point state (md_closure).
  virtual void update_stress(const Points<Dim>& p, double dt) = 0;
  // Longitudinal sound speed of point q (for the artificial viscosity; the CFL limit's
  // unless signal_speed says otherwise).
  virtual double sound_speed(const Points<Dim>& p, std::size_t q) const = 0;
  // The fastest wave of point q at its current state, for the stable step (mpm/step_limit):
  // the sound speed, unless the law's own stiffness grows with its compression beyond what
  // sound_speed says (md_closure: its crystal's tangent modulus at the point's J).
  virtual double signal_speed(const Points<Dim>& p, std::size_t q) const { return sound_speed(p, q); }
  // Energy stored in point q (elastic strain energy, or internal energy), for the
  // energy balance of run.json; zero where the law keeps no such account.
  virtual double stored_energy(const Points<Dim>&, std::size_t) const { return 0.0; }
  // The sum of stored_energy over points [begin, end), in an order fixed by the range
  // alone (a law may sum in lanes that vectorise).
  virtual double stored_energy_sum(const Points<Dim>& p, std::size_t begin, std::size_t end) const {
    double s = 0.0;
    for (std::size_t q = begin; q < end; ++q) s += stored_energy(p, q);
    return s;
  }
  // The work dt q : D of the artificial viscous stress q, which a law that keeps an
  // energy account (Mie-Gruneisen) adds as heat; nothing by default.
  virtual void add_viscous_heat(const Points<Dim>&, const std::array<double*, Dim * Dim>&, double) {}
  // Threads a law spreads its points over (results never depend on them: every point's
  // update is its own).
  virtual void set_threads(int threads) { threads_ = threads > 0 ? threads : 1; }
  // The run's --threads as asked (0: OpenMP's default), for a law that spreads work of
  // its own over them (md_closure's boxes); called before initialize.
  virtual void use_run_threads(int /*requested*/) {}
  // The work a law does inside its points, when it runs a model of its own there.
  virtual const Subscale* subscale() const { return nullptr; }
  // 2-D and 3-D: whether stored_energy is the law's whole account of the energy it holds
  // (strain or internal energy), so that kinetic plus stored energy less the boundary's
  // work is the run's total, which must not grow (the energy-growth check of a run).
  virtual bool keeps_energy_account() const { return false; }
  // 1-D: whether ADMPM's energy account of the bar (eq. 8.26) covers this law, whose
  // stored_energy is then summed into the run's energy balance (the elastic bar only).
  virtual bool stored_energy_in_1d() const { return false; }
  // 1-D: the law as the fused kernels take it, where it has such a form.
  virtual const FusedElastic1d* fused_elastic() const { return nullptr; }
  // Under MPI: spread the per-point state anew over the ranks from its measured cost
  // when the slowest rank's time since the last call exceeds `threshold` x the mean
  // (collective; called at checkpoints). True when state moved. Results never depend
  // on it.
  virtual bool rebalance(double /*threshold*/) { return false; }
  // What the law carries per point beyond the points' arrays, for the output (none by
  // default). Under MPI every rank holds the same values.
  virtual std::vector<PointField> point_fields(const Points<Dim>&) const { return {}; }
  // Point q's own model as a file of its own (md_closure: its MD box as a LAMMPS dump
  // frame at `step`); "" where the law runs none. Collective under MPI (the rank that runs
  // the box sends it): rank 0's answer is the file, the others get "".
  virtual std::string point_model_dump(std::size_t /*q*/, std::int64_t /*step*/,
                                       const std::vector<std::string>& /*fields*/) const {
    return {};
  }
  // Whether the law runs a model of its own inside point q (what point_model_dump writes).
  virtual bool runs_point_model(std::size_t /*q*/) const { return false; }
  // Per-point state beyond the point arrays, for checkpoints (none by default).
  virtual void save(std::ostream&) const {}
  virtual void load(std::istream&) {}
  // The points the per-point state is for (after load, checked against the deck's), or
  // -1 when the law keeps none.
  virtual long long state_points() const { return -1; }

 protected:
  int threads_ = 1;
};

}  // namespace mpmx::material
