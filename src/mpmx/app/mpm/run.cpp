#include "mpmx/app/mpm/run.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "mpmx/app/mpm/box_dumps.hpp"
#include "mpmx/app/mpm/checkpoint.hpp"
#include "mpmx/app/mpm/comparison.hpp"
#include "mpmx/app/mpm/convergence.hpp"
#include "mpmx/app/mpm/gauges.hpp"
#include "mpmx/app/mpm/output.hpp"
#include "mpmx/app/mpm/prepare.hpp"
#include "mpmx/app/mpm/run_checkpoint.hpp"
#include "mpmx/app/mpm/run_summary.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/app/mpm/signal_speed.hpp"
#include "mpmx/app/mpm/time_rows.hpp"
#include "mpmx/app/mpm/vtk_output.hpp"
#include "mpmx/app/mpm/xt_diagram.hpp"
#include "mpmx/app/run_folder.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/interrupt.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/io/plot.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/mpm/nodal_fields.hpp"
#include "mpmx/mpm/piston_grid.hpp"
#include "mpmx/mpm/state_checks.hpp"
#include "mpmx/mpm/step_limit.hpp"
#include "mpmx/mpm/step.hpp"
#include "mpmx/mpm/sums.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// The steps at which a run records its fields and compares them with its reference
// (dt = "cfl": the record times, each step landing on the next).
struct Schedule {
  std::int64_t steps;
  std::set<std::int64_t> record_steps, compare_steps;
  std::int64_t energy_every;
  double energy_interval = 0.0;  // dt = "cfl": by time (time_rows.hpp)
  std::vector<double> record_times, compare_times;

  explicit Schedule(const MpmConfig& c) : steps(c.steps()), record_steps{0, steps} {
    for (double t : c.output_times) record_steps.insert(std::llround(t / c.dt));
    for (double t : c.reference.times) {
      compare_steps.insert(std::llround(t / c.dt));
      record_steps.insert(std::llround(t / c.dt));
    }
    energy_every = std::max<std::int64_t>(1, steps / 2000);
    if (c.cfl_dt) energy_interval = c.end / 2000.0;
    record_times.assign(c.output_times.begin(), c.output_times.end());
    record_times.insert(record_times.end(), c.reference.times.begin(), c.reference.times.end());
    record_times.push_back(c.end);
    std::sort(record_times.begin(), record_times.end());
    compare_times = c.reference.times;
  }

  // Whether step n, from t0 to t1, checks the energy and volumes: every energy_every
  // steps, or with dt = "cfl" at each 1/2000 of the run's time.
  bool observes(std::int64_t n, double t0, double t1) const {
    return energy_interval > 0.0 ? passes_multiple(t0, t1, energy_interval) : n % energy_every == 0;
  }

  // dt = "cfl": whether the step that landed at t landed on a reference time.
  bool compares_at(double t) const {
    for (double r : compare_times)
      if (std::abs(t - r) <= 1e-12 * std::max(1.0, r)) return true;
    return false;
  }
};

// One continuum run: the state, its comparison, its outputs and the loop that advances
// them (dissertation sec. 3.1; mpm/step.cpp is one step).
template <int Dim>
class ContinuumRun {
 public:
  ContinuumRun(const MpmConfig& deck, const RunOptions& o, RunResultOf<Dim>& r)
      : o_(o), r_(r), s_(r.state), folder_(o.out_dir, o.resume, o.owner), c_(prepare(deck)), schedule_(c_),
        book_(rec_), comparison_(make_comparison<Dim>(c_)) {
    const MpmConfig& c = c_;
    {
      // Ctrl-C while the MD boxes are built ends the run cleanly (md_closure stops there).
      InterruptGuard building(folder_.checkpoints);
      r.state = make_state<Dim>(c, !o.resume, o.threads);
      if (InterruptGuard::interrupted())
        throw Interrupted("while the run was being set up: nothing was written; start the run again");
    }
    gauges_ = std::make_unique<Gauges<Dim>>(c, s_, o.out_dir.empty());  // from the initial state
    const material::Subscale* sub = s_.material->subscale();
    r.threads = sub ? sub->threads() : 1;
    rec_.set("version", MPMX_VERSION);
    rec_.set("deck", c.deck);
    rec_.set("deck_path", c.deck_path);
    // A resumed run takes these from its checkpoint, and its law's per-point state is not
    // loaded yet: nothing is summed before the load.
    const Sums s0 = o.resume ? Sums{} : sums(s_);
    carry_ = {s0.momentum, s0.kinetic, s0.mass, s0.abs_momentum, s0.kinetic, s0.internal, 0.0, StepLog{}};
    Output::Marks marks;
    // Every rank reads the checkpoint (and keeps its block of the laws' state).
    if (o.resume) ranks::together([&] {
      marks = load_run_checkpoint(checkpoint_path(folder_.dir), c, s_, carry_, book_, rec_);
    });
    rec_.set("threads", r.threads);
    rec_.set("materials", material_labels());
    rec_.set("ranks", static_cast<std::int64_t>(ranks::size()));
    ranks::together([&] {  // output from rank 0 only; a folder it cannot make stops all
      if (o.out_dir.empty() || !ranks::root()) return;
      std::filesystem::create_directories(folder_.dir);
      if (o.resume)  // a stopped run's final tables: the resumed run goes on from its checkpoint
        for (const char* f : {"final_particles.csv", "final_nodes.csv"}) std::filesystem::remove(folder_.dir + "/" + f);
      out_ = std::make_unique<Output>(folder_.dir, Dim == 1 && c.write_nodes, Dim == 1 && c.write_particles, marks);
      if (c.write_vtk) vtk_ = std::make_unique<VtkOutput<Dim>>(folder_.dir, o.resume ? s_.time : -1.0);
      if (c.write_xt) xt_ = std::make_unique<XtDiagram<Dim>>(c, s_.grid);
    });
    // Every rank takes part in a dump (the box may run on any); rank 0 writes it.
    if (!c.md_dump_points.empty() && !o.out_dir.empty())
      dumps_ = std::make_unique<BoxDumps<Dim>>(folder_.dir, c.md_dump_points, c.md_dump_fields, *s_.material);
  }

  // The step loop: each step, then the checks, comparisons, records and checkpoints it
  // is due; a RunError (the physics stopped the run) ends it with the state as it was.
  void run() {
    Progress progress(fmt::format("{} {}", c_.id, scheme_name(c_.scheme.scheme)), schedule_.steps,
                      o_.quiet || !ranks::root(), s_.step);
    t0_ = std::chrono::steady_clock::now();
    first_step_ = s_.step;
    InterruptGuard guard(folder_.checkpoints);
    try {
      if (!o_.resume) {
        record();
        observe();
        gauges_->sample(s_, out_.get());
        if (xt_) xt_->sample(s_, s_.time, *out_);
      }
      for (std::int64_t n = s_.step + 1; !done(n); ++n) {
        const double t_before = s_.time;
        const bool at_record_time = advance(n);
        check_finite(s_);
        gauges_->sample(s_, out_.get());
        if (xt_) xt_->sample(s_, t_before, *out_);
        const bool last = c_.cfl_dt ? !(s_.time < c_.end) : n == schedule_.steps;
        const bool compare =
            c_.cfl_dt ? at_record_time && schedule_.compares_at(s_.time) : schedule_.compare_steps.count(n) > 0;
        if (compare && comparison_) comparison_->compare(s_, book_);
        if (due_record(n, at_record_time)) record();
        if (dumps_ && c_.md_dump_every > 0 && n % c_.md_dump_every == 0) dumps_->write(s_);
        if (schedule_.observes(n, t_before, s_.time) || last) {
          check_volumes(s_);
          observe();
        }
        if (c_.cfl_dt) {  // the steps ahead are not known
          progress.note(carry_.steps.last());
          progress.update(n, s_.time / c_.end);
        } else {
          progress.update(n);
        }
        if (folder_.checkpoints && !last && checkpoint_or_stop(n)) {
          r_.interrupted = true;
          break;
        }
      }
      if (!r_.interrupted) progress.finish(s_.step);
    } catch (const RunError& e) {
      // The same on every rank: the continuum checks read the replicated state, and the
      // closure and the checkpoint agree on theirs (core/ranks).
      ranks::mark_agreed();
      failure_ = e.what();
      record_final();
    }
    finish();
  }

 private:
  // The deck with its laws' preparation done (md_closure's NPT box: prepare.hpp), before
  // anything is built, its note said first; Ctrl-C there ends the run as while the boxes
  // are built.
  MpmConfig prepare(const MpmConfig& deck) {
    if (!o_.resume && !o_.quiet && ranks::root() && deck.material.spec)
      if (const std::string note = deck.material.spec->build_note(); !note.empty())
        fmt::print(stderr, "{}: {}\n", deck.id, note);
    InterruptGuard preparing(folder_.checkpoints);
    MpmConfig c;
    ranks::together([&] { c = prepared_for_run(deck); });  // alike on every rank (one thread each)
    if (InterruptGuard::interrupted())
      throw Interrupted("while the run was being prepared (md_closure's NPT box, before the points' boxes): nothing "
                        "was written and there is nothing to resume; start the run again");
    return c;
  }

  bool done(std::int64_t n) const { return c_.cfl_dt ? !(s_.time < c_.end) : n > schedule_.steps; }

  // Step n: dt from the deck, or (dt = "cfl") from the state (mpm/step_limit.hpp), in
  // whole quanta of the law's (md_closure: MD steps) and shortened to land on the next
  // record time. True when it landed on one.
  bool advance(std::int64_t n) {
    if (!c_.cfl_dt) {
      step(s_, c_.dt);
      s_.time = n * c_.dt;  // no drift from summing dt
      return false;
    }
    const auto& times = schedule_.record_times;
    const double t0 = s_.time;
    const auto next = std::upper_bound(times.begin(), times.end(), t0 * (1.0 + 1e-12));
    const double t_next = next == times.end() ? c_.end : *next;
    const StepLimit limit = step_limit(s_, {c_.cfl, c_.max_volume_strain});
    double h = whole_quanta(limit.dt, quantum_), t1 = t0 + h;
    if (quantum_ > 0.0) {
      // Times as whole quanta: the record times are (the deck's reading), and so is every
      // step, so no sum of steps drifts off them.
      const double k0 = std::round(t0 / quantum_), k = std::round(h / quantum_);
      t1 = (k0 + k) * quantum_;
    }
    const double h_state = h;
    const bool lands = t1 >= t_next * (1.0 - 1e-12);
    if (lands) h = t_next - t0, t1 = t_next;
    step(s_, h);
    s_.time = t1;
    carry_.steps.add(n, t1, h, h < h_state ? StepLimiter::record_time : limit.by, limit);
    return lands;
  }

  bool due_record(std::int64_t n, bool at_record_time) const {
    return (c_.cfl_dt ? at_record_time : schedule_.record_steps.count(n) > 0) ||
           (c_.output_every > 0 && n % c_.output_every == 0);
  }

  void record() {
    if (vtk_) vtk_->record(s_);
    if constexpr (Dim == 1)
      if (out_) out_->record(s_, nodal_fields(s_), comparison_ ? comparison_->solution() : nullptr);
    if (comparison_) comparison_->at_record(s_, book_, out_.get());
    if (dumps_ && (c_.md_dump_every == 0 || s_.step == 0)) dumps_->write(s_);
  }

  // What the points' `material` ids name: each law's model and the bodies whose points
  // take it (ids in the order the laws' first points come, x fastest: the deck's
  // [material] is 0).
  toml::array material_labels() const {
    const auto& p = s_.particles;
    std::map<int, std::set<int>> bodies;
    for (std::size_t q = 0; q < p.size(); ++q) bodies[p.law[q]].insert(p.body[q]);
    toml::array out;
    for (const auto& [law, of] : bodies) {
      const int b = *of.begin();
      const bool own = law > 0 && b < static_cast<int>(c_.bodies.size()) && c_.bodies[b].material;
      const material::Model* m = own ? c_.bodies[b].material.get() : c_.material.spec.get();
      toml::array ids;
      for (int i : of) ids.push_back(i);
      toml::table entry{{"id", law},
                        {"model", m ? m->name() : std::string("?")},
                        {"from", own ? "[[body]] " + std::to_string(b) + " [body.material]" : "[material]"},
                        {"bodies", std::move(ids)}};
      // The constants the law runs with (those a potential gave, say, which no deck shows).
      if (m && !m->constants().empty()) {
        toml::table k;
        for (const auto& [name, value] : m->constants()) k.insert(name, value);
        entry.insert("constants", std::move(k));
        entry.insert("constants_from", m->constants_source());
      }
      out.push_back(std::move(entry));
    }
    return out;
  }

  // The state a stopped run ends in, written as the regular records are but named
  // final (vtk/particles_final_NNNNNN.vtu, last in particles.pvd; final_particles.csv and
  // final_nodes.csv in 1-D) and said in run.json's "final_record", so the failing state
  // can be seen. A part the state cannot give (a point past the grid has no nodal
  // fields) is left out and said there.
  void record_final() {
    if (o_.out_dir.empty() || !ranks::root()) return;
    toml::table said{{"step", s_.step}, {"time", s_.time}, {"reason", failure_}};
    toml::array files, missing;
    auto attempt = [&](const char* what, auto&& write) {
      try {
        write();
        files.push_back(what);
      } catch (const std::exception& e) {  // what the failed state cannot give
        missing.push_back(fmt::format("{}: {}", what, e.what()));
      }
    };
    if (vtk_) attempt("vtk/particles_final (.vtu, .vti)", [&] { vtk_->record(s_, true); });
    if constexpr (Dim == 1)
      if (out_ && (c_.write_particles || c_.write_nodes)) {
        if (c_.write_particles) attempt("final_particles.csv", [&] {
          Output last(folder_.dir, false, true, {}, "final_");
          last.record(s_, NodalFields{}, nullptr);
          last.close();
        });
        if (c_.write_nodes) attempt("final_nodes.csv", [&] {
          Output last(folder_.dir, true, false, {}, "final_");
          last.record(s_, nodal_fields(s_), nullptr);
          last.close();
        });
      }
    said.insert("files", std::move(files));
    if (!missing.empty()) said.insert("not_written", std::move(missing));
    rec_.set("final_record", std::move(said));
  }

  // The energy balance's figures, and the energy error against a reference that knows
  // the total energy.
  void observe() {
    const Sums now = sums(s_);
    carry_.max_kinetic = std::max({carry_.max_kinetic, now.kinetic, grid_frame_kinetic(now)});
    const Reference* ref = comparison_ ? comparison_->solution() : nullptr;
    const double e_ref = ref ? ref->total_energy(s_.time) : std::nan("");
    if (std::isfinite(e_ref)) {
      auto& e = book_.errors["energy"];
      e.l1 = std::max(e.l1, std::abs(now.kinetic + now.internal - e_ref));
      e.l2 = std::max(e.l2, e_ref);  // running max of the reference, normalised in finish()
    }
    check_energy_growth(now);
    if (out_)
      out_->energy(s_.step, s_.time, now.kinetic, now.internal, Dim == 1 ? now.momentum[0] : norm(now.momentum),
                   Dim == 1 ? s_.tallies.boundary_impulse[0] : norm(s_.tallies.boundary_impulse), e_ref);
  }

  // The points' kinetic energy relative to the grid, sum m |v - u|^2 / 2 with u the
  // grid's velocity: the lab's where no piston carries the grid. In the grid's frame a
  // piston is the wall, the bar running at -u_p onto it, and the energy in play is the
  // wall run's from the first step, where a piston's work and the lab's kinetic energy
  // are still near zero. The balance itself is read in the lab; it is the wall run's, as
  // the piston's impulse is the momentum's change and its work u_p times that.
  double grid_frame_kinetic(const Sums& now) const {
    const auto u = grid_velocity<Dim>(s_.boundary, s_.time);
    double k = now.kinetic, u2 = 0.0;
    for (int a = 0; a < Dim; ++a) k -= u[a] * now.momentum[a], u2 += u[a] * u[a];
    return k + 0.5 * now.mass * u2;
  }

  // The total energy (kinetic + stored) less the work put in, against the initial:
  // its growth over the larger of the initial total, the total with the boundary's work
  // and the largest kinetic energy seen (in the lab or the grid's frame). An unstable
  // update (the midpoint form's determinant > 1, theory.md) or too long a step shows
  // here first; past time.energy_growth_stop the run stops where it is.
  void check_energy_growth(const Sums& now) {
    const bool known = Dim == 1 ? s_.material->stored_energy_in_1d() : s_.material->keeps_energy_account();
    if (!known) return;
    // What the boundary and a manufactured solution's body force (N4) put in is not growth.
    const double e0 = carry_.kinetic_initial + carry_.stored_initial, wb = s_.tallies.boundary_work + s_.tallies.body_work;
    const double scale = std::max({std::abs(e0), std::abs(e0 + wb), carry_.max_kinetic});
    if (!(scale > 0.0)) return;
    r_.energy_growth = (now.kinetic + now.internal - wb - e0) / scale;
    if (r_.energy_growth > c_.energy_growth_stop) {
      r_.energy_grew = true;
      throw RunError(fmt::format(
          "energy growth at step {} (t = {:.6g}): the total energy (kinetic + stored, less the work put in) grew "
          "by {:.4g} of its scale {:.6g}, past time.energy_growth_stop = {:.4g}; the update is unstable: a smaller "
          "time.dt, or scheme.update_velocity = \"musl\" (the default) if the deck chose another",
          s_.step, s_.time, r_.energy_growth, scale, c_.energy_growth_stop));
    }
  }

  // A checkpoint when one is due (every so many steps or minutes, or on Ctrl-C); true
  // when the run is to stop there. Under MPI the ranks act together: any rank's signal,
  // rank 0's clock.
  bool checkpoint_or_stop(std::int64_t n) {
    bool stop = InterruptGuard::interrupted() || n == o_.stop_after;
    // Long runs of small steps read the clock every 64 steps: reading it costs a good
    // part of such a step.
    const std::int64_t clock_every = schedule_.steps >= 100000 ? 64 : 1;
    const bool by_count = o_.checkpoint_every > 0 && n % o_.checkpoint_every == 0;
    bool by_time = o_.checkpoint_seconds > 0 && n % clock_every == 0 &&
                   wall() - carry_.wall_before - last_checkpoint_ >= o_.checkpoint_seconds;
    if (ranks::size() > 1) {
      const auto agreed = ranks::max({stop ? 1.0 : 0.0, by_time && ranks::root() ? 1.0 : 0.0});
      stop = agreed[0] > 0, by_time = agreed[1] > 0;
    }
    if (stop || by_count || by_time) {
      ranks::together([&] { save_checkpoint(); });
      last_checkpoint_ = wall() - carry_.wall_before;
      if (!stop) ranks::together([&] { r_.rebalances += s_.material->rebalance(o_.rebalance_above); });
    }
    return stop;
  }

  // Collective under MPI (the laws gather their per-point state); rank 0 writes. The wall
  // time so far is saved as the next process's earlier time.
  void save_checkpoint() {
    RunCarry carry = carry_;
    carry.wall_before = wall();
    save_run_checkpoint(checkpoint_path(folder_.dir), c_, s_, carry, book_, rec_,
                        out_ ? out_->marks() : Output::Marks{});
  }

  double wall() const {
    return carry_.wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

  // The run's figures into the result and run.json; the folder published; the figures drawn.
  void finish() {
    r_.wall_seconds = wall();
    r_.steps = s_.step;
    r_.steps_now = s_.step - first_step_;
    const material::Subscale* sub = s_.material->subscale();
    if (sub) r_.md_atom_steps = sub->steps();
    // The slowest rank's MD time over the mean (1 on one rank).
    const double md_mine = sub ? sub->seconds() : 0.0;
    const double md_slowest = ranks::max({md_mine})[0], md_mean = ranks::sum(md_mine) / ranks::size();
    r_.rank_imbalance = md_mean > 0 ? md_slowest / md_mean : 1.0;
    r_.ranks = ranks::size();
    if (book_.eq712.squared_reference > 0) r_.stress_vs_direct_md = book_.eq712.value();
    tally();
    if (std::isfinite(r_.energy_growth) && r_.energy_growth > c_.energy_growth) r_.energy_grew = true;
    if (r_.energy_grew && failure_.empty() && !o_.quiet && ranks::root())
      fmt::print(stderr,
                 "{}: warning: the total energy grew by {:.3g} of its scale (time.energy_growth = {:.3g}): the "
                 "update may be unstable (a smaller time.dt, or scheme.update_velocity = \"musl\"); run.json's status "
                 "is \"energy_growth\"\n",
                 c_.id, r_.energy_growth, c_.energy_growth);
    if (comparison_) comparison_->finish(book_);
    r_.errors = book_.errors;
    r_.gauges = gauges_->traces();
    r_.front_speed = book_.front_speed;
    if (c_.cfl_dt) {
      rec_.set("time_steps", carry_.steps.record());
      r_.time_steps = carry_.steps.summary();
    }
    record_run(c_, r_, failure_, checkpoint_path(o_.out_dir), rec_);
    if (!o_.out_dir.empty() && ranks::root()) {
      if (out_) out_->close();  // before run.json: a table the disk cut short fails the run
      out_.reset();
      rec_.write(folder_.dir + "/run.json");
      if (failure_.empty() && !r_.interrupted) std::filesystem::remove(checkpoint_path(folder_.dir));
      folder_.publish();
      if (failure_.empty() && !r_.interrupted && o_.plot && c_.plot) plot();
    }
    if (!failure_.empty()) throw RunError(failure_);
  }

  // Conservation: the sums at the start (carried) and now, the step's tallies.
  void tally() {
    const Sums s1 = sums(s_);
    auto& r = r_;
    r.momentum_initial_vec = carry_.momentum_initial;
    r.kinetic_initial = carry_.kinetic_initial;
    r.mass_particles = carry_.mass_particles;
    r.stored_initial = carry_.stored_initial;
    r.max_kinetic = carry_.max_kinetic;
    r.momentum_final_vec = s1.momentum;
    r.stored_final = s1.internal;
    r.boundary_impulse_vec = s_.tallies.boundary_impulse;
    r.momentum_initial = r.momentum_initial_vec[0];
    r.momentum_final = r.momentum_final_vec[0];
    r.kinetic_final = s1.kinetic;
    r.momentum_scale = std::max(carry_.momentum_scale, s1.abs_momentum);
    r.boundary_impulse = s_.tallies.boundary_impulse[0];
    r.boundary_work = s_.tallies.boundary_work;
    r.body_work = s_.tallies.body_work;
    r.stress_work = s_.tallies.stress_work;
    r.max_force_sum = s_.tallies.max_force_sum;
    r.mass_nodes = s_.tallies.node_mass;
    if (auto it = book_.errors.find("energy"); it != book_.errors.end()) {
      // Largest deviation over t, relative to the largest reference energy.
      const double rel = it->second.l2 > 0 ? it->second.l1 / it->second.l2 : 0.0;
      it->second = {rel, rel};
    }
  }

  void plot() const {
    if (!io::matplotlib_present()) return;
    if (Dim == 1) io::run_plot_script("mpmx_plot.py", fmt::format("--quiet '{}'", o_.out_dir));
    else if (Dim == 2 && vtk_)
      // Frames over the run (first, peak, last): the last record alone can mislead, e.g.
      // two disks after their rebound show only their ringing.
      io::run_plot_script("points2d.py", fmt::format("'{}/particles.pvd' --field stress --component xx --frames 4 "
                                                     "--out '{}/stress_xx.png' >/dev/null",
                                                     o_.out_dir, o_.out_dir));
    // The gauges' histories and the x-t diagram (figures/gauges.png, xt_sigma_xx.png).
    if (!c_.gauges.empty() || xt_) io::run_plot_script("gauges.py", fmt::format("--quiet '{}'", o_.out_dir));
  }

  const RunOptions& o_;
  RunResultOf<Dim>& r_;
  State<Dim>& s_;
  RunFolder folder_;
  const MpmConfig c_;  // the deck, its laws prepared
  Schedule schedule_;
  io::RunRecord rec_;
  ErrorBook book_;
  std::unique_ptr<Comparison<Dim>> comparison_;
  RunCarry carry_;
  std::unique_ptr<Output> out_;
  std::unique_ptr<VtkOutput<Dim>> vtk_;
  std::unique_ptr<Gauges<Dim>> gauges_;
  std::unique_ptr<XtDiagram<Dim>> xt_;
  std::unique_ptr<BoxDumps<Dim>> dumps_;
  std::string failure_;
  std::chrono::steady_clock::time_point t0_;
  double last_checkpoint_ = 0.0;
  std::int64_t first_step_ = 0;  // where this invocation started
  const double quantum_ = time_quantum(c_);  // dt = "cfl": steps are whole numbers of it (0: any)
};

}  // namespace

template <int Dim>
RunResultOf<Dim> run_mpm_dim(const MpmConfig& c, const RunOptions& o) {
  RunResultOf<Dim> r;
  ContinuumRun<Dim>(c, o, r).run();
  return r;
}

template RunResultOf<1> run_mpm_dim<1>(const MpmConfig&, const RunOptions&);
template RunResultOf<2> run_mpm_dim<2>(const MpmConfig&, const RunOptions&);
template RunResultOf<3> run_mpm_dim<3>(const MpmConfig&, const RunOptions&);

RunResult run_mpm(const MpmConfig& c, const RunOptions& o) {
  if (c.dim != 1) throw InputError(fmt::format("run_mpm runs 1-D decks; this one has grid.dim = {}", c.dim));
  return run_mpm_dim<1>(c, o);
}

RunSummary run_any(const MpmConfig& c, const RunOptions& o) {
  auto summary = [](const auto& r) {
    RunSummary s;
    s.steps = r.steps;
    s.steps_now = r.steps_now;
    s.wall_seconds = r.wall_seconds;
    s.particles = r.state.particles.size();
    s.interrupted = r.interrupted;
    s.time = r.state.time;
    s.errors = r.errors;
    s.md_atom_steps = r.md_atom_steps;
    s.threads = r.threads;
    s.ranks = r.ranks;
    s.rank_imbalance = r.rank_imbalance;
    s.stress_vs_direct_md = r.stress_vs_direct_md;
    s.energy_growth = r.energy_growth;
    s.energy_grew = r.energy_grew;
    s.energy_balance_error = r.energy_scale() > 0 ? r.energy_error() / r.energy_scale() : 0.0;
    s.time_steps = r.time_steps;
    return s;
  };
  if (c.convergence_levels > 1) {
    const ConvergenceStudy study = run_convergence(c, o);
    RunSummary s = study.levels.back().run;
    s.convergence_order = study.order_l2;
    return s;
  }
  switch (c.dim) {
    case 1: return summary(run_mpm_dim<1>(c, o));
    case 2: return summary(run_mpm_dim<2>(c, o));
    case 3: return summary(run_mpm_dim<3>(c, o));
  }
  throw InputError(fmt::format("grid.dim = {}: must be 1, 2 or 3", c.dim));
}

}  // namespace mpmx::app
