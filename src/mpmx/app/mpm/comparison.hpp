#pragma once
// What a run compares with its reference solution, and how: the deck's [reference] names
// an entry (app/mpm/references.hpp) that makes the run's Comparison. The errors it finds,
// pooled over the compared times, go into an ErrorBook, which a checkpoint carries.
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mpmx/app/mpm/config.hpp"
#include "mpmx/app/mpm/reference.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/mpm/state.hpp"
#include "mpmx/reference/bar_history.hpp"
#include "mpmx/reference/norms.hpp"

namespace mpmx::app {

class Output;

struct FieldError {
  double l1 = 0.0, l2 = 0.0;  // max over the compared times
  double peak = 0.0;          // max |u - r| / max |r - b|: overshoot and spikes
};

// The errors of a run so far: each field's norms (the max over the compared times, and
// every time's in run.json's errors.<field>.by_time), eq. 7.12 pooled over the compared
// times (direct_md), and the shock fronts found (shock_front).
class ErrorBook {
 public:
  explicit ErrorBook(io::RunRecord& rec) : rec_(&rec) {}

  std::map<std::string, FieldError> errors;   // by field; also "energy", "front_speed"
  reference::Eq712 eq712;                     // pooled over the compared times
  std::vector<std::pair<double, double>> fronts;  // (t, x)
  double front_speed = 0.0;

  // One field's norms at time t.
  void add(const std::string& field, const reference::ErrorNorms& n, double peak, double t);
  // The norms of u against uref (weights w) and the peak error, relative to the larger of
  // the disturbance from `baseline` now and `scale` (over the run), at time t (nothing when
  // u is empty).
  void add_samples(const std::string& field, const std::vector<double>& u, const std::vector<double>& uref,
                   const std::vector<double>& w, double baseline, double t, const reference::ErrorScale& scale = {});
  // Eq. 7.12 of one compared time, in run.json's errors_by_time.stress_vs_direct_md.
  void add_eq712(const reference::Eq712& now, double t);
  io::RunRecord& record() { return *rec_; }

 private:
  io::RunRecord* rec_;
};

template <int Dim>
class Comparison {
 public:
  virtual ~Comparison() = default;
  // At a compared time.
  virtual void compare(const mpm::State<Dim>& s, ErrorBook& book) = 0;
  // At a record (after the tables are written).
  virtual void at_record(const mpm::State<Dim>&, ErrorBook&, Output*) {}
  // The field solution, where the comparison has one (the 1-D tables' reference columns,
  // the total energy).
  virtual const Reference* solution() const { return nullptr; }
  // At the end: what the whole run shows (a front speed).
  virtual void finish(ErrorBook&) const {}
};

// The comparison the deck's [reference] asks for (nullptr: none). Throws InputError when
// the deck does not suit its reference.
template <int Dim>
std::unique_ptr<Comparison<Dim>> make_comparison(const MpmConfig& c);

// Value of a named field of particle q (1-D).
double particle_field(const mpm::Particles<1>& p, const std::string& field, std::size_t q);

// A field reference compared at the points: in 1-D at every particle (or node, with
// reference.at = "nodes"); in 2-D and 3-D along the normal of the initial profile
// `along`, over the points no wall has signalled to yet. `pool_eq712`: each particle's stress is also pooled into
// eq. 7.12 against the solution (the 1-D direct-MD bar).
template <int Dim>
class FieldComparison final : public Comparison<Dim> {
 public:
  FieldComparison(const MpmConfig& c, std::unique_ptr<Reference> ref, const Profile& along, bool pool_eq712 = false);
  void compare(const mpm::State<Dim>& s, ErrorBook& book) override;
  const Reference* solution() const override { return ref_.get(); }

 private:
  void compare_1d(const mpm::State<Dim>& s, ErrorBook& book);
  void compare_along_normal(const mpm::State<Dim>& s, ErrorBook& book);
  // The field's disturbance over the run's compared times (reference/norms.hpp).
  const reference::ErrorScale& scale(const std::string& field);
  const MpmConfig& c_;
  std::unique_ptr<Reference> ref_;
  const Profile& along_;
  bool pool_eq712_;
  std::vector<double> u_, uref_, w_;
  std::map<std::string, reference::ErrorScale> scale_;
};

}  // namespace mpmx::app
