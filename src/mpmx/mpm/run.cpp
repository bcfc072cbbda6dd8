#include "mpmx/mpm/run.hpp"

#include "mpmx/mpm/convergence.hpp"
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <typeinfo>
#include <utility>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/core/ranks.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/plot.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/material/md_closure.hpp"
#include "mpmx/io/checked_file.hpp"
#include "mpmx/io/staged_dir.hpp"
#include "mpmx/mpm/checkpoint.hpp"
#include "mpmx/mpm/convergence.hpp"
#include "mpmx/mpm/nodal_fields.hpp"
#include "mpmx/mpm/output.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/vtk_output.hpp"
#include "mpmx/reference/jet_history.hpp"
#include "mpmx/material/linear_elastic.hpp"
#include "mpmx/material/md_closure_model.hpp"
#include "mpmx/mpm/reference.hpp"
#include "mpmx/mpm/setup.hpp"
#include "mpmx/mpm/step.hpp"
#include "mpmx/reference/bar_history.hpp"
#include "mpmx/reference/norms.hpp"
#include "mpmx/reference/shock_front.hpp"

namespace mpmx::mpm {

namespace {

double norm(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

struct Sums {
  double kinetic = 0.0, abs_momentum = 0.0, internal = 0.0, mass = 0.0;
  std::array<double, 3> momentum{};
};

template <int Dim>
Sums sums(const State<Dim>& s) {
  const auto& p = s.particles;
  const auto view = points(p);
  // 1-D keeps ADMPM's stored energy of the elastic bar (eq. 8.26) and no other.
  const bool elastic_1d = Dim == 1 && typeid(*s.material) == typeid(material::LinearElastic<1>);
  auto add_1d = [&](Sums& r, std::size_t q) {
    const double mv = p.mass[q] * p.v[0][q];
    r.momentum[0] += mv;
    r.kinetic += 0.5 * mv * p.v[0][q];
    r.abs_momentum += std::abs(mv);
    if (elastic_1d) r.internal += 0.5 * p.volume0[q] * p.stress[0][q] * p.strain[0][q];
    r.mass += p.mass[q];
  };
  Sums r;
  const std::size_t n = p.size();
  if constexpr (Dim == 1) {
    for (std::size_t q = 0; q < n; ++q) add_1d(r, q);
  } else {
    // Blocks of a fixed size on the threads, added in block order; within a block, eight
    // lanes by the point's place in it, added in lane order (the loop vectorises): the
    // same sums for any thread count.
    constexpr std::size_t kBlock = 2048, kLanes = 8;
    std::vector<Sums> part((n + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(static) num_threads(s.threads) if (s.threads > 1)
    for (std::size_t b = 0; b < part.size(); ++b) {
      const std::size_t q0 = b * kBlock, q1 = std::min(n, q0 + kBlock);
      double ke[kLanes] = {}, am[kLanes] = {}, m[kLanes] = {}, mom[Dim][kLanes] = {};
      auto lane = [&](std::size_t q, std::size_t l) {
        double v2 = 0.0;
        for (int a = 0; a < Dim; ++a) {
          mom[a][l] += p.mass[q] * p.v[a][q];
          v2 += p.v[a][q] * p.v[a][q];
        }
        ke[l] += 0.5 * p.mass[q] * v2;
        am[l] += p.mass[q] * std::sqrt(v2);
        m[l] += p.mass[q];
      };
      std::size_t q = q0;
      for (; q + kLanes <= q1; q += kLanes)
        for (std::size_t l = 0; l < kLanes; ++l) lane(q + l, l);
      for (std::size_t l = 0; q < q1; ++q, ++l) lane(q, l);
      Sums& out = part[b];
      for (std::size_t l = 0; l < kLanes; ++l) {
        out.kinetic += ke[l], out.abs_momentum += am[l], out.mass += m[l];
        for (int a = 0; a < Dim; ++a) out.momentum[a] += mom[a][l];
      }
      out.internal = s.material->stored_energy_sum(view, q0, q1);
    }
    for (const Sums& b : part) {
      r.kinetic += b.kinetic, r.abs_momentum += b.abs_momentum, r.internal += b.internal, r.mass += b.mass;
      for (int a = 0; a < Dim; ++a) r.momentum[a] += b.momentum[a];
    }
  }
  return r;
}

// A NaN or Inf anywhere stops the run naming the step, the particle and the field.
// The cheap per-step test is the sum of the new velocities and positions (from g2p)
// and the stress work of the step: any non-finite value poisons them.
template <int Dim>
void check_finite(const State<Dim>& s) {
  if (std::isfinite(s.finite_check) && std::isfinite(s.tallies.stress_work)) return;
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q) {
    if (!std::isfinite(p.volume[q]))
      throw RunError(fmt::format("non-finite volume ({}) at particle {} in step {} (t = {})", p.volume[q], q,
                                 s.step, s.time));
    for (int a = 0; a < Dim; ++a) {
      const std::pair<const char*, double> fields[] = {
          {"velocity", p.v[a][q]}, {"stress", p.stress[a * Dim + a][q]}, {"position", p.x[a][q]}};
      for (const auto& [name, v] : fields)
        if (!std::isfinite(v))
          throw RunError(fmt::format("non-finite {} ({}) at particle {} in step {} (t = {})", name,
                                     v, q, s.step, s.time));
    }
  }
  throw RunError(fmt::format("non-finite stress work in step {} (t = {})", s.step, s.time));
}

// The CFL step of the current state: cfl x the smallest cell side / max over points of
// (sound speed + speed); a maximum, so the same for any thread count.
template <int Dim>
double stable_dt(const State<Dim>& s, double cfl) {
  const auto& p = s.particles;
  const auto view = points(p);
  double dx = s.grid.dx[0], fastest = 0.0;
  for (int d = 1; d < Dim; ++d) dx = std::min(dx, s.grid.dx[d]);
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static) reduction(max : fastest) num_threads(s.threads) if (s.threads > 1)
  for (std::size_t q = 0; q < n; ++q) {
    double v2 = 0.0;
    for (int a = 0; a < Dim; ++a) v2 += p.v[a][q] * p.v[a][q];
    fastest = std::max(fastest, s.material->sound_speed(view, q) + std::sqrt(v2));
  }
  if (!(fastest > 0.0) || !std::isfinite(fastest))
    throw RunError(fmt::format("dt = \"cfl\": no finite wave speed in step {} (t = {})", s.step, s.time));
  return cfl * dx / fastest;
}

// A particle whose volume is no longer positive has failed (tension or compression
// instability): checked where the volumes are read anyway, at the records.
template <int Dim>
void check_volumes(const State<Dim>& s) {
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (!(p.volume[q] > 0.0))
      throw RunError(fmt::format("volume of particle {} fell to {} in step {} (t = {}): the "
                                 "material failed (tension or compression instability)",
                                 q, p.volume[q], s.step, s.time));
}

// Ctrl-C asks the step loop to write a checkpoint and stop; a second one kills. Under
// MPI, SIGTERM does the same: mpirun turns a Ctrl-C into SIGTERM to every rank, and
// a batch system's time limit sends it too.
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int sig) {
  g_interrupted = 1;
  std::signal(sig, SIG_DFL);
}
class InterruptGuard {
 public:
  explicit InterruptGuard(bool active) : active_(active), term_(active && ranks::active()) {
    if (!active_) return;
    g_interrupted = 0;
    previous_ = std::signal(SIGINT, on_interrupt);
    if (term_) previous_term_ = std::signal(SIGTERM, on_interrupt);
  }
  ~InterruptGuard() {
    if (active_) std::signal(SIGINT, previous_);
    if (term_) std::signal(SIGTERM, previous_term_);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  bool active_, term_;
  void (*previous_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

std::string deck_text(const MpmConfig& c) {
  std::ostringstream ss;
  ss << c.deck;
  return ss.str();
}

}  // namespace

std::string checkpoint_path(const std::string& out_dir) { return out_dir + "/checkpoint.bin"; }

template <int Dim>
RunResultOf<Dim> run_mpm_dim(const MpmConfig& config, const RunOptions& o) {
  const MpmConfig& c = config;
  const bool checkpoints = !o.out_dir.empty();
  if (o.resume && !checkpoints) throw InputError("resuming needs the run's output directory");
  // Where this process writes (io/staged_dir.hpp): a fresh run in OUT/.staging, moved
  // into OUT once it ends; a resumed run where its checkpoint lies (OUT, or the staging
  // folder of a run that was killed before it ended).
  const bool resume_staged = o.resume && !std::filesystem::exists(checkpoint_path(o.out_dir)) &&
                             std::filesystem::exists(checkpoint_path(io::StagedDir::staging_of(o.out_dir)));
  if (o.resume && !resume_staged && !std::filesystem::exists(checkpoint_path(o.out_dir)))
    throw InputError(fmt::format("no checkpoint to resume from: {} does not exist", checkpoint_path(o.out_dir)));
  // Under MPI the ranks agree on it after all have looked, before rank 0 (the only writer)
  // touches the folder.
  const bool staged = checkpoints && (!o.resume || ranks::max({resume_staged ? 1.0 : 0.0})[0] > 0.0);
  std::optional<io::StagedDir> stage;
  if (staged && ranks::root()) stage.emplace(o.out_dir, o.resume);
  const std::string dir = staged ? io::StagedDir::staging_of(o.out_dir) : o.out_dir;
  RunResultOf<Dim> r;
  const bool md_closure = dynamic_cast<const material::MdClosureModel*>(c.material.spec.get()) != nullptr;
  if (!o.resume && !o.quiet && md_closure && ranks::root())
    fmt::print(stderr, "{}: building the MD box of every point ({} atoms each, section 6.2)...\n", c.id,
               c.material.md.atoms_per_point());
  r.state = make_state<Dim>(c, !o.resume, o.threads);
  State<Dim>& s = r.state;
  const auto* closure = dynamic_cast<const material::MdClosure<Dim>*>(s.material.get());
  r.threads = closure ? closure->threads() : 1;
  const auto ref = make_reference(c);  // 2-D, 3-D: a 1-D solution along the profile's normal
  // 2-D and 3-D direct MD: the binned maps of a jet run, each point against its bin.
  std::optional<reference::JetHistory> jet;
  std::optional<units::UnitSystem> jet_units;
  if (Dim > 1 && c.reference.name == "direct_md") {
    jet = reference::JetHistory::read(c.reference.file);
    jet_units = units::unit_system(c.units);
    for (double t : c.reference.times)
      if (!jet->has(t * jet_units->time_ps))
        throw InputError(fmt::format("{} has no record at t = {} ({} ps); its last is at {} ps", c.reference.file, t,
                                     t * jet_units->time_ps, jet->last_time_ps()));
  }
  const bool track_front = c.reference.name == "shock_front";
  const std::int64_t steps = c.steps();
  const double dt = c.dt;

  std::set<std::int64_t> record_steps{0, steps}, compare_steps;
  for (double t : c.output_times) record_steps.insert(std::llround(t / dt));
  for (double t : c.reference.times) {
    compare_steps.insert(std::llround(t / dt));
    record_steps.insert(std::llround(t / dt));
  }
  const std::int64_t energy_every = std::max<std::int64_t>(1, steps / 2000);

  io::RunRecord rec;
  rec.set("version", MPMX_VERSION);
  rec.set("deck", c.deck);
  rec.set("deck_path", c.deck_path);

  // A resumed run takes these from its checkpoint (carried() below), and its law's
  // per-point state is not loaded yet: nothing is summed before the load.
  const Sums s0 = o.resume ? Sums{} : sums(s);
  r.momentum_initial_vec = s0.momentum;
  r.stored_initial = s0.internal;
  r.kinetic_initial = s0.kinetic;
  r.mass_particles = s0.mass;
  r.momentum_scale = s0.abs_momentum;
  r.max_kinetic = s0.kinetic;

  std::vector<std::pair<double, double>> fronts;  // (t, x)
  reference::Eq712 eq712;                          // pooled over the compared times
  const bool direct_md = c.reference.name == "direct_md";
  double wall_before = 0.0;                        // earlier processes of a resumed run

  // The run loop's own running figures, carried by a checkpoint after the state.
  auto carried = [&] {
    return std::array<double*, 11>{&r.momentum_initial_vec[0], &r.momentum_initial_vec[1], &r.momentum_initial_vec[2],
                                   &r.kinetic_initial, &r.mass_particles, &r.momentum_scale,
                                   &r.max_kinetic, &eq712.squared_difference, &eq712.squared_reference,
                                   &wall_before, &r.stored_initial};
  };
  // Collective under MPI (the material gathers its per-point state); rank 0 writes.
  auto save_checkpoint = [&](Output* out, double wall_now) {
    const std::string path = checkpoint_path(dir);
    const bool writer = ranks::root();
    {
      std::ostringstream f(std::ios::binary);  // every rank fills it; rank 0 writes it
      CheckpointOut w(f);
      w.text(deck_text(c));
      save_state(w, s);
      const double before = std::exchange(wall_before, wall_now);  // saved as the next process's
      for (const double* v : carried()) w.number(*v);
      wall_before = before;
      w.integer(static_cast<std::int64_t>(r.errors.size()));
      for (const auto& [name, e] : r.errors) {
        w.text(name);
        w.numbers({e.l1, e.l2, e.peak});
      }
      std::vector<double> fr;
      for (const auto& [t, x] : fronts) fr.push_back(t), fr.push_back(x);
      w.numbers(fr);
      std::ostringstream table;
      table << rec.table();
      w.text(table.str());
      const Output::Marks marks = out ? out->marks() : Output::Marks{};
      w.integer(static_cast<std::int64_t>(marks.size()));
      for (const auto& [name, bytes] : marks) {
        w.text(name);
        w.integer(bytes);
      }
      if (!f) throw RunError(fmt::format("cannot write the checkpoint {}", path));
      if (writer) io::write_checked(path, run_checkpoint_kind(deck_text(c), s.particles.size()), f.view());
    }
  };
  Output::Marks resume_marks;
  // Every rank reads the checkpoint (and keeps its block of the material's state).
  if (o.resume) ranks::together([&] {
    const std::string path = checkpoint_path(dir);
    std::istringstream f(io::read_checked(path, run_checkpoint_kind(deck_text(c), s.particles.size())),
                         std::ios::binary);
    CheckpointIn in(f, path, io::kCheckedHeaderBytes);
    if (in.text() != deck_text(c))
      throw InputError(fmt::format("{} was written for another deck (the deck changed since); run afresh "
                                   "without --resume",
                                   path));
    load_state(in, s);
    // A checkpoint is written before the last step, never at or past it.
    if (!c.cfl_dt && s.step >= steps)
      throw in.refuse(io::kCheckedHeaderBytes, fmt::format("step {} is at or past the deck's last step {}", s.step, steps));
    if (!(s.time < c.end))
      throw in.refuse(io::kCheckedHeaderBytes, fmt::format("time {} is at or past the deck's end {}", s.time, c.end));
    for (double* v : carried()) *v = in.number();
    for (std::int64_t k = in.integer(); k > 0; --k) {
      const long long at = in.offset();
      const std::string name = in.text();
      const auto e = in.numbers();
      if (e.size() != 3) throw in.refuse(at, "an error norm of other than 3 numbers");
      r.errors[name] = {e[0], e[1], e[2]};
    }
    const auto fr = in.numbers();
    for (std::size_t k = 0; k + 1 < fr.size(); k += 2) fronts.emplace_back(fr[k], fr[k + 1]);
    const long long at_rec = in.offset();
    try {
      rec.assign(toml::parse(in.text()));
    } catch (const toml::parse_error& e) {
      throw in.refuse(at_rec, fmt::format("its run record does not parse: {}", e.what()));
    }
    for (std::int64_t k = in.integer(); k > 0; --k) {
      const long long at_name = in.offset();
      const std::string name = in.text();
      // A table of the run directory itself: never a path that leads out of it.
      if (name.empty() || name.find_first_of("/\\") != std::string::npos || name.front() == '.')
        throw in.refuse(at_name, fmt::format("'{}' is not a table name of a run directory", name));
      const long long at = in.offset();
      const std::int64_t bytes = in.integer();
      if (bytes < 0) throw in.refuse(at, fmt::format("a table length of {} bytes", bytes));
      resume_marks[name] = bytes;
    }
    if (f.peek() != std::char_traits<char>::eof()) throw in.refuse(in.offset(), "trailing bytes after the state");
  });
  rec.set("threads", r.threads);
  rec.set("ranks", static_cast<std::int64_t>(ranks::size()));
  std::unique_ptr<Output> out;
  std::unique_ptr<VtkOutput<Dim>> vtk;
  ranks::together([&] {  // output from rank 0 only; a folder it cannot make stops all
    if (o.out_dir.empty() || !ranks::root()) return;
    std::filesystem::create_directories(dir);
    out = std::make_unique<Output>(dir, Dim == 1 && c.write_nodes, Dim == 1 && c.write_particles, resume_marks);
    if (c.write_vtk) vtk = std::make_unique<VtkOutput<Dim>>(dir, o.resume ? s.time : -1.0);
  });
  std::vector<double> u, uref, w;
  // Shock-front plateaus: the strain behind the right-going front is the mean of the
  // two initial states (the step splits into two half-amplitude waves).
  const double ahead = c.strain.right, behind = 0.5 * (c.strain.left + c.strain.right);
  const double front_c0 = std::sqrt(c.material.youngs_modulus / c.material.density);

  // One field's norms at this time: kept as the max over the compared times and by time.
  auto record_error = [&](const std::string& f, const reference::ErrorNorms& n, double peak) {
    auto& e = r.errors[f];
    e.l1 = std::max(e.l1, n.l1);
    e.l2 = std::max(e.l2, n.l2);
    e.peak = std::max(e.peak, peak);
    toml::table at;
    at.insert("time", s.time);
    at.insert("l1", n.l1);
    at.insert("l2", n.l2);
    at.insert("peak", peak);
    rec.append(fmt::format("errors.{}.by_time", f), std::move(at));
  };
  // Relative norms of u against uref (weights w) and the peak error over the disturbance.
  auto record_samples = [&](const std::string& f, double baseline) {
    if (u.empty()) return;
    const auto n = reference::relative_error_norms(u, uref, w, baseline);
    double dmax = 0.0, rmax = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
      dmax = std::max(dmax, std::abs(u[k] - uref[k]));
      rmax = std::max(rmax, std::abs(uref[k] - baseline));
    }
    record_error(f, n, rmax > 0.0 ? dmax / rmax : 0.0);
  };

  auto compare = [&]() {
    const auto& p = s.particles;
    if constexpr (Dim > 1) {
      if (s.manufactured) {
        for (const auto& f : c.reference.fields) record_error(f, s.manufactured->displacement_error(p, s.time), 0.0);
        return;
      }
      if (jet) {  // eq. 7.12 on sigma_xx; the continuum's x = 0 is the piston's face
        reference::Eq712 now;
        const double t_ps = s.time * jet_units->time_ps, L = jet_units->length_A;
        for (std::size_t q = 0; q < p.size(); ++q) {
          const double md = jet->sxx(t_ps, jet->piston_face_A() + L * p.x[0][q], L * p.x[1][q]);
          if (!std::isfinite(md)) continue;  // outside the bins, or an empty bin
          now.add(p.stress[0][q], md / jet_units->stress_GPa);
          eq712.add(p.stress[0][q], md / jet_units->stress_GPa);
        }
        toml::table at;
        at.insert("time", s.time);
        at.insert("error", now.value());
        rec.append("errors_by_time.stress_vs_direct_md", std::move(at));
        return;
      }
      if (!ref || !ref->valid(s.time)) return;
      // Along the normal of the initial profile, over the points no wall has signalled
      // to yet: farther than (fastest signal) t + 2 cells from every face.
      const Profile& prof = c.reference.name == "riemann_isothermal" ? c.pressure : c.velocity;
      double dx_max = 0.0;
      for (int d = 0; d < Dim; ++d) dx_max = std::max(dx_max, s.grid.dx[d]);
      const double speed = ref->signal_speed();
      const double margin = (std::isfinite(speed) ? speed * s.time : 0.0) + 2.0 * dx_max;
      for (const auto& f : c.reference.fields) {
        u.clear(), uref.clear(), w.clear();
        for (std::size_t q = 0; q < p.size(); ++q) {
          std::array<double, 3> x{};
          bool inside = true;
          for (int d = 0; d < Dim; ++d) {
            x[d] = p.x[d][q];
            inside = inside && x[d] - s.grid.lower[d] > margin && s.grid.upper[d] - x[d] > margin;
          }
          if (!inside) continue;
          double value = 0.0, vn = 0.0, snn = 0.0, tr = 0.0;
          for (int a = 0; a < Dim; ++a) {
            vn += p.v[a][q] * prof.normal[a];
            tr += p.stress[a * Dim + a][q];
            for (int b = 0; b < Dim; ++b) snn += prof.normal[a] * p.stress[a * Dim + b][q] * prof.normal[b];
          }
          if (f == "velocity") value = vn;
          else if (f == "pressure") value = -tr / Dim;
          else if (f == "stress") value = snn;
          else if (f == "density") value = p.mass[q] / p.volume[q];
          else value = p.strain[0][q];
          u.push_back(value);
          uref.push_back(ref->value(f, prof.along(x, Dim), s.time));
          w.push_back(p.volume[q]);
        }
        record_samples(f, ref->baseline(f));
      }
    } else {
      if (!ref || !ref->valid(s.time)) return;
      if (direct_md) {  // eq. 7.12: every point against the direct-MD bin it lies in
        reference::Eq712 now;
        for (std::size_t q = 0; q < p.size(); ++q) {
          const double md = ref->value("stress", p.x[0][q], s.time);
          now.add(p.stress[0][q], md);
          eq712.add(p.stress[0][q], md);
        }
        toml::table at;
        at.insert("time", s.time);
        at.insert("error", now.value());
        rec.append("errors_by_time.stress_vs_direct_md", std::move(at));
      }
      const NodalFields nf = c.reference.at_nodes ? nodal_fields(s) : NodalFields{};
      for (const auto& f : c.reference.fields) {
        u.clear(), uref.clear(), w.clear();
        if (c.reference.at_nodes) {
          for (std::size_t i = 0; i < nf.size(); ++i) {
            if (nf.mass[i] <= 0.0) continue;
            u.push_back(nf.field(f, i));
            uref.push_back(ref->value(f, nf.x[i], s.time));
            w.push_back(nf.volume[i]);
          }
        } else {
          for (std::size_t q = 0; q < p.size(); ++q) {
            u.push_back(particle_field(p, f, q));
            uref.push_back(ref->value(f, p.x[0][q], s.time));
            w.push_back(p.volume[q]);
          }
        }
        record_samples(f, ref->baseline(f));
      }
    }
  };
  auto observe = [&]() {
    const Sums now = sums(s);
    r.max_kinetic = std::max(r.max_kinetic, now.kinetic);
    const double e_ref = ref ? ref->total_energy(s.time) : std::nan("");
    if (std::isfinite(e_ref)) {
      auto& e = r.errors["energy"];
      e.l1 = std::max(e.l1, std::abs(now.kinetic + now.internal - e_ref));
      e.l2 = std::max(e.l2, e_ref);  // running max of the reference, normalised below
    }
    if (out)
      out->energy(s.step, s.time, now.kinetic, now.internal, Dim == 1 ? now.momentum[0] : norm(now.momentum),
                  Dim == 1 ? s.tallies.boundary_impulse[0] : norm(s.tallies.boundary_impulse), e_ref);
  };
  auto record = [&]() {
    if (vtk) vtk->record(s);
    if constexpr (Dim == 1) {
    if (out) out->record(s, nodal_fields(s), ref.get());
    if (track_front && s.step > 0) {
      const auto& p = s.particles;
      std::vector<double> xs(p.x[0]), fs(p.strain[0]);
      const auto x = reference::locate_front(xs, fs, behind, ahead, reference::ScanFrom::right);
      if (x) {
        fronts.emplace_back(s.time, *x);
        if (out) out->front(s.time, *x, c.strain.at + front_c0 * s.time);
      }
    }
    }
  };

  Progress progress(fmt::format("{} {}", c.id, scheme_name(c.scheme.scheme)), steps, o.quiet || !ranks::root(),
                    s.step);
  const auto t0 = std::chrono::steady_clock::now();
  auto wall = [&] { return wall_before + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  double last_checkpoint = 0.0;
  const std::int64_t clock_every = steps >= 100000 ? 64 : 1;
  InterruptGuard guard(checkpoints);
  std::string failure;
  try {
    if (!o.resume) {
      record();
      observe();
    }
    // dt = "cfl": each step's dt from the state, shortened to land on the next record
    // time; the run ends at time.end.
    std::vector<double> record_times(c.output_times.begin(), c.output_times.end());
    record_times.push_back(c.end);
    std::sort(record_times.begin(), record_times.end());
    auto done = [&](std::int64_t n) { return c.cfl_dt ? !(s.time < c.end) : n > steps; };
    for (std::int64_t n = s.step + 1; !done(n); ++n) {
      bool at_record_time = false;
      if (c.cfl_dt) {
        const double t0 = s.time;
        const auto next = std::upper_bound(record_times.begin(), record_times.end(), t0 * (1.0 + 1e-12));
        const double t_next = next == record_times.end() ? c.end : *next;
        double h = stable_dt(s, c.cfl);
        if (t0 + h >= t_next * (1.0 - 1e-12)) h = t_next - t0, at_record_time = true;
        step(s, h);
        s.time = at_record_time ? t_next : t0 + h;
      } else {
        step(s, dt);
        s.time = n * dt;  // no drift from summing dt
      }
      check_finite(s);
      const bool last = c.cfl_dt ? !(s.time < c.end) : n == steps;
      const bool is_record = (c.cfl_dt ? at_record_time : record_steps.count(n) > 0) ||
                             (c.output_every > 0 && n % c.output_every == 0);
      if (compare_steps.count(n)) compare();
      if (is_record) record();
      if (n % energy_every == 0 || last) {
        check_volumes(s);
        observe();
      }
      progress.update(c.cfl_dt ? std::min<std::int64_t>(steps - 1, std::llround(s.time / c.end * steps)) : n);
      if (checkpoints && !last) {
        bool stop = g_interrupted || n == o.stop_after;
        // Long runs of small steps read the clock every 64 steps: reading it costs a
        // good part of such a step.
        const bool by_count = o.checkpoint_every > 0 && n % o.checkpoint_every == 0;
        bool by_time = o.checkpoint_seconds > 0 && n % clock_every == 0 &&
                       wall() - wall_before - last_checkpoint >= o.checkpoint_seconds;
        if (ranks::size() > 1) {  // the ranks act together: any rank's signal, rank 0's clock
          const auto agreed = ranks::max({stop ? 1.0 : 0.0, by_time && ranks::root() ? 1.0 : 0.0});
          stop = agreed[0] > 0, by_time = agreed[1] > 0;
        }
        if (stop || by_count || by_time) {
          ranks::together([&] { save_checkpoint(out.get(), wall()); });
          last_checkpoint = wall() - wall_before;
          if (!stop) ranks::together([&] { r.rebalances += s.material->rebalance(o.rebalance_above); });
        }
        if (stop) {
          r.interrupted = true;
          break;
        }
      }
    }
    if (!r.interrupted) progress.finish();
  } catch (const RunError& e) {
    // The same on every rank: the continuum checks read the replicated state, and the
    // closure and the checkpoint agree on theirs (core/ranks).
    ranks::mark_agreed();
    failure = e.what();
  }
  r.wall_seconds = wall();
  r.steps = s.step;
  if (closure) r.md_atom_steps = closure->atom_steps();
  // The slowest rank's MD time over the mean (1 on one rank).
  const double md_mine = closure ? closure->md_seconds() : 0.0;
  const double md_slowest = ranks::max({md_mine})[0], md_mean = ranks::sum(md_mine) / ranks::size();
  r.rank_imbalance = md_mean > 0 ? md_slowest / md_mean : 1.0;
  r.ranks = ranks::size();
  if (direct_md && eq712.squared_reference > 0) r.stress_vs_direct_md = eq712.value();

  const Sums s1 = sums(s);
  r.momentum_final_vec = s1.momentum;
  r.stored_final = s1.internal;
  r.boundary_impulse_vec = s.tallies.boundary_impulse;
  r.momentum_initial = r.momentum_initial_vec[0];
  r.momentum_final = r.momentum_final_vec[0];
  r.kinetic_final = s1.kinetic;
  r.momentum_scale = std::max(r.momentum_scale, s1.abs_momentum);
  r.boundary_impulse = s.tallies.boundary_impulse[0];
  r.boundary_work = s.tallies.boundary_work;
  r.stress_work = s.tallies.stress_work;
  r.max_force_sum = s.tallies.max_force_sum;
  r.mass_nodes = s.tallies.node_mass;
  if (auto it = r.errors.find("energy"); it != r.errors.end()) {
    // Largest deviation over t, relative to the largest reference energy.
    const double rel = it->second.l2 > 0 ? it->second.l1 / it->second.l2 : 0.0;
    it->second = {rel, rel};
  }
  if (track_front && fronts.size() >= 2) {
    std::vector<double> ts, xs;
    for (const auto& [t, x] : fronts) ts.push_back(t), xs.push_back(x);
    r.front_speed = reference::front_speed(ts, xs);
    const double c0 = front_c0;
    const double rel = std::abs(r.front_speed - c0) / c0;
    r.errors["front_speed"] = {rel, rel};
    rec.set("front_speed", r.front_speed);
    rec.set("reference_speed", c0);
  }

  rec.set("status", !failure.empty() ? "stopped" : r.interrupted ? "interrupted" : "completed");
  if (r.interrupted) rec.set("checkpoint", checkpoint_path(o.out_dir));
  if (std::isfinite(r.stress_vs_direct_md)) rec.set("errors.stress_vs_direct_md", r.stress_vs_direct_md);
  if (const auto u = units::unit_system(c.units)) {  // for readers of the tables (tools/plot)
    rec.set("units.name", std::string(u->name));
    rec.set("units.length_A", u->length_A);
    rec.set("units.time_ps", u->time_ps);
    rec.set("units.stress_GPa", u->stress_GPa);
  }
  if (closure) {
    const auto& eq = closure->equilibrium();
    rec.set("md_atom_steps", r.md_atom_steps);
    rec.set("md_atom_steps_per_second", r.wall_seconds > 0 ? r.md_atom_steps / r.wall_seconds : 0.0);
    rec.set("md.atoms_per_point", closure->atoms_per_point());
    rec.set("md.points", static_cast<std::int64_t>(s.particles.size()));
    rec.set("md.lattice_constant_A", eq.lattice_constant);
    rec.set("md.energy_per_atom_eV", eq.energy_per_atom);
    rec.set("md.c11_GPa", eq.c11_gpa);
    rec.set("md.density", closure->density());
    rec.set("md.energy_injected_eV", closure->energy_injected_ev());   // eq. 7.11, running total
    rec.set("md.energy_shortfall_eV", closure->energy_shortfall_ev());
    rec.set("md.neighbor_builds", closure->neighbor_builds());
  }
  rec.set("rank_imbalance", r.rank_imbalance);
  if (r.ranks > 1) rec.set("rebalances", static_cast<std::int64_t>(r.rebalances));
  if (!failure.empty()) rec.set("error", failure);
  rec.set("dim", static_cast<std::int64_t>(Dim));
  rec.set("steps", static_cast<std::int64_t>(r.steps));
  rec.set("time", s.time);
  rec.set("wall_seconds", r.wall_seconds);
  rec.set("particles", static_cast<std::int64_t>(s.particles.size()));
  rec.set("particle_steps_per_second",
          r.wall_seconds > 0 ? static_cast<double>(s.particles.size()) * r.steps / r.wall_seconds : 0.0);
  if (s.phases.total() > 0)  // the stencil step's phases, seconds of this invocation (not the fused 1-D step's)
    for (std::size_t k = 0; k < kPhaseNames.size(); ++k) rec.set(fmt::format("phases.{}", kPhaseNames[k]), s.phases.seconds[k]);
  for (const auto& [f, e] : r.errors) {
    rec.set(fmt::format("errors.{}.l1", f), e.l1);
    rec.set(fmt::format("errors.{}.l2", f), e.l2);
    if (e.peak > 0.0) rec.set(fmt::format("errors.{}.peak", f), e.peak);
  }
  rec.set("conservation.mass.particles", r.mass_particles);
  rec.set("conservation.mass.nodes", r.mass_nodes);
  rec.set("conservation.mass.relative_error", std::abs(r.mass_nodes - r.mass_particles) / r.mass_particles);
  if constexpr (Dim == 1) {
    rec.set("conservation.momentum.initial", r.momentum_initial);
    rec.set("conservation.momentum.final", r.momentum_final);
    rec.set("conservation.momentum.boundary_impulse", r.boundary_impulse);
  } else {  // vector norms, and the vectors
    rec.set("conservation.momentum.initial", norm(r.momentum_initial_vec));
    rec.set("conservation.momentum.final", norm(r.momentum_final_vec));
    rec.set("conservation.momentum.boundary_impulse", norm(r.boundary_impulse_vec));
    rec.set("conservation.momentum.initial_vector",
            std::vector<double>(r.momentum_initial_vec.begin(), r.momentum_initial_vec.begin() + Dim));
    rec.set("conservation.momentum.final_vector",
            std::vector<double>(r.momentum_final_vec.begin(), r.momentum_final_vec.begin() + Dim));
    rec.set("conservation.momentum.boundary_impulse_vector",
            std::vector<double>(r.boundary_impulse_vec.begin(), r.boundary_impulse_vec.begin() + Dim));
    rec.set("conservation.energy.stored_initial", r.stored_initial);
    rec.set("conservation.energy.stored_final", r.stored_final);
    const double e0 = r.kinetic_initial + r.stored_initial, e1 = r.kinetic_final + r.stored_final;
    rec.set("conservation.energy.total_initial", e0);
    rec.set("conservation.energy.total_final", e1);
    rec.set("conservation.energy.total_relative_change", e0 != 0.0 ? (e1 - e0 - r.boundary_work) / e0 : 0.0);
  }
  rec.set("conservation.momentum.relative_error",
          r.momentum_scale > 0 ? r.momentum_error() / r.momentum_scale : 0.0);
  rec.set("conservation.momentum.max_internal_force_sum", r.max_force_sum);
  rec.set("conservation.energy.kinetic_initial", r.kinetic_initial);
  rec.set("conservation.energy.kinetic_final", r.kinetic_final);
  rec.set("conservation.energy.stress_work", r.stress_work);
  rec.set("conservation.energy.boundary_work", r.boundary_work);
  rec.set("conservation.energy.error", r.energy_error());
  rec.set("conservation.energy.relative_error", r.max_kinetic > 0 ? r.energy_error() / r.max_kinetic : 0.0);

  if (!o.out_dir.empty() && ranks::root()) {
    out.reset();  // close the tables before plotting
    rec.write(dir + "/run.json");
    if (failure.empty() && !r.interrupted) std::filesystem::remove(checkpoint_path(dir));
    if (stage) stage->publish();
    if (failure.empty() && !r.interrupted && o.plot && c.plot && (Dim == 1 || (Dim == 2 && vtk)) &&
        io::matplotlib_present()) {
      if (Dim == 1) io::run_plot_script("mpmx_plot.py", fmt::format("--quiet '{}'", o.out_dir));
      else
        io::run_plot_script("points2d.py", fmt::format("'{}/particles.pvd' --field stress --component xx "
                                                       "--out '{}/stress_xx.png' >/dev/null",
                                                       o.out_dir, o.out_dir));
    }
  }
  if (!failure.empty()) throw RunError(failure);
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
    s.wall_seconds = r.wall_seconds;
    s.particles = r.state.particles.size();
    s.interrupted = r.interrupted;
    s.errors = r.errors;
    s.md_atom_steps = r.md_atom_steps;
    s.threads = r.threads;
    s.ranks = r.ranks;
    s.rank_imbalance = r.rank_imbalance;
    s.stress_vs_direct_md = r.stress_vs_direct_md;
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

}  // namespace mpmx::mpm
