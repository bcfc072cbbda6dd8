#include "mpmx/mpm/run.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/mpm/nodal_fields.hpp"
#include "mpmx/mpm/output.hpp"
#include "mpmx/mpm/reference.hpp"
#include "mpmx/mpm/setup.hpp"
#include "mpmx/mpm/step.hpp"
#include "mpmx/reference/norms.hpp"
#include "mpmx/reference/shock_front.hpp"

namespace mpmx::mpm {

namespace {

struct Sums {
  double kinetic = 0.0, momentum = 0.0, abs_momentum = 0.0, internal = 0.0, mass = 0.0;
};

Sums sums(const Particles<1>& p, bool solid) {
  Sums s;
  for (std::size_t q = 0; q < p.size(); ++q) {
    const double mv = p.mass[q] * p.v[0][q];
    s.kinetic += 0.5 * mv * p.v[0][q];
    s.momentum += mv;
    s.abs_momentum += std::abs(mv);
    s.mass += p.mass[q];
    // Stored elastic energy in the reference configuration (ADMPM eq. 8.26).
    if (solid) s.internal += 0.5 * p.volume0[q] * p.stress[0][q] * p.strain[0][q];
  }
  return s;
}

// A NaN or Inf anywhere stops the run naming the step, the particle and the field.
// The cheap per-step test is the sum of the new velocities and positions (from g2p)
// and the stress work of the step: any non-finite value poisons them.
void check_finite(const State<1>& s) {
  if (std::isfinite(s.finite_check) && std::isfinite(s.tallies.stress_work)) return;
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q) {
    const std::pair<const char*, double> fields[] = {
        {"velocity", p.v[0][q]}, {"stress", p.stress[0][q]}, {"position", p.x[0][q]},
        {"volume", p.volume[q]}};
    for (const auto& [name, v] : fields)
      if (!std::isfinite(v))
        throw RunError(fmt::format("non-finite {} ({}) at particle {} in step {} (t = {})", name,
                                   v, q, s.step, s.time));
  }
  throw RunError(fmt::format("non-finite stress work in step {} (t = {})", s.step, s.time));
}

// A particle whose volume is no longer positive has failed (tension or compression
// instability): checked where the volumes are read anyway, at the records.
void check_volumes(const State<1>& s) {
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (!(p.volume[q] > 0.0))
      throw RunError(fmt::format("volume of particle {} fell to {} in step {} (t = {}): the "
                                 "material failed (tension or compression instability)",
                                 q, p.volume[q], s.step, s.time));
}

bool matplotlib_present() {
  return std::system(MPMX_PYTHON " -c 'import matplotlib, numpy' >/dev/null 2>&1") == 0;
}

}  // namespace

RunResult run_mpm(const MpmConfig& c, const RunOptions& o) {
  RunResult r;
  r.state = make_state(c);
  State<1>& s = r.state;
  const auto ref = make_reference(c);
  const bool solid = c.material.model == "linear_elastic";
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

  std::unique_ptr<Output> out;
  if (!o.out_dir.empty()) {
    std::filesystem::create_directories(o.out_dir);
    out = std::make_unique<Output>(o.out_dir, c.write_nodes, c.write_particles);
  }
  io::RunRecord rec;
  rec.set("version", MPMX_VERSION);
  rec.set("deck", c.deck);
  rec.set("deck_path", c.deck_path);
  rec.set("threads", 1);

  const Sums s0 = sums(s.particles, solid);
  r.momentum_initial = s0.momentum;
  r.kinetic_initial = s0.kinetic;
  r.mass_particles = s0.mass;
  r.momentum_scale = s0.abs_momentum;
  r.max_kinetic = s0.kinetic;

  std::vector<std::pair<double, double>> fronts;  // (t, x)
  std::vector<double> u, uref, w;
  // Shock-front plateaus: the strain behind the right-going front is the mean of the
  // two initial states (the step splits into two half-amplitude waves).
  const double ahead = c.strain.right, behind = 0.5 * (c.strain.left + c.strain.right);
  const double front_c0 = std::sqrt(c.material.youngs_modulus / c.material.density);

  auto compare = [&]() {
    if (!ref || !ref->valid(s.time)) return;
    const auto& p = s.particles;
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
      const auto n = reference::relative_error_norms(u, uref, w, ref->baseline(f));
      double dmax = 0.0, rmax = 0.0;
      for (std::size_t k = 0; k < u.size(); ++k) {
        dmax = std::max(dmax, std::abs(u[k] - uref[k]));
        rmax = std::max(rmax, std::abs(uref[k] - ref->baseline(f)));
      }
      const double peak = rmax > 0.0 ? dmax / rmax : 0.0;
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
    }
  };
  auto observe = [&]() {
    const Sums now = sums(s.particles, solid);
    r.max_kinetic = std::max(r.max_kinetic, now.kinetic);
    const double e_ref = ref ? ref->total_energy(s.time) : std::nan("");
    if (std::isfinite(e_ref)) {
      auto& e = r.errors["energy"];
      e.l1 = std::max(e.l1, std::abs(now.kinetic + now.internal - e_ref));
      e.l2 = std::max(e.l2, e_ref);  // running max of the reference, normalised below
    }
    if (out)
      out->energy(s.step, s.time, now.kinetic, now.internal, now.momentum,
                  s.tallies.boundary_impulse, e_ref);
  };
  auto record = [&]() {
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
  };

  Progress progress(fmt::format("{} {}", c.id, scheme_name(c.scheme.scheme)), steps, o.quiet);
  const auto t0 = std::chrono::steady_clock::now();
  std::string failure;
  try {
    record();
    observe();
    for (std::int64_t n = 1; n <= steps; ++n) {
      step(s, dt);
      s.time = n * dt;  // no drift from summing dt
      check_finite(s);
      const bool is_record = record_steps.count(n) || (c.output_every > 0 && n % c.output_every == 0);
      if (compare_steps.count(n)) compare();
      if (is_record) record();
      if (n % energy_every == 0 || n == steps) {
        check_volumes(s);
        observe();
      }
      progress.update(n);
    }
    progress.finish();
  } catch (const RunError& e) {
    failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.steps = s.step;

  const Sums s1 = sums(s.particles, solid);
  r.momentum_final = s1.momentum;
  r.kinetic_final = s1.kinetic;
  r.momentum_scale = std::max(r.momentum_scale, s1.abs_momentum);
  r.boundary_impulse = s.tallies.boundary_impulse;
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

  rec.set("status", failure.empty() ? "completed" : "stopped");
  if (!failure.empty()) rec.set("error", failure);
  rec.set("steps", static_cast<std::int64_t>(r.steps));
  rec.set("time", s.time);
  rec.set("wall_seconds", r.wall_seconds);
  rec.set("particles", static_cast<std::int64_t>(s.particles.size()));
  rec.set("particle_steps_per_second",
          r.wall_seconds > 0 ? static_cast<double>(s.particles.size()) * r.steps / r.wall_seconds : 0.0);
  for (const auto& [f, e] : r.errors) {
    rec.set(fmt::format("errors.{}.l1", f), e.l1);
    rec.set(fmt::format("errors.{}.l2", f), e.l2);
    if (e.peak > 0.0) rec.set(fmt::format("errors.{}.peak", f), e.peak);
  }
  rec.set("conservation.mass.particles", r.mass_particles);
  rec.set("conservation.mass.nodes", r.mass_nodes);
  rec.set("conservation.mass.relative_error", std::abs(r.mass_nodes - r.mass_particles) / r.mass_particles);
  rec.set("conservation.momentum.initial", r.momentum_initial);
  rec.set("conservation.momentum.final", r.momentum_final);
  rec.set("conservation.momentum.boundary_impulse", r.boundary_impulse);
  rec.set("conservation.momentum.relative_error",
          r.momentum_scale > 0 ? r.momentum_error() / r.momentum_scale : 0.0);
  rec.set("conservation.momentum.max_internal_force_sum", r.max_force_sum);
  rec.set("conservation.energy.kinetic_initial", r.kinetic_initial);
  rec.set("conservation.energy.kinetic_final", r.kinetic_final);
  rec.set("conservation.energy.stress_work", r.stress_work);
  rec.set("conservation.energy.boundary_work", r.boundary_work);
  rec.set("conservation.energy.error", r.energy_error());
  rec.set("conservation.energy.relative_error", r.max_kinetic > 0 ? r.energy_error() / r.max_kinetic : 0.0);

  if (!o.out_dir.empty()) {
    out.reset();  // close the tables before plotting
    rec.write(o.out_dir + "/run.json");
    if (failure.empty() && o.plot && c.plot && matplotlib_present()) {
      const std::string cmd = fmt::format("{} {}/tools/plot/mpmx_plot.py --quiet '{}'", MPMX_PYTHON,
                                          MPMX_SOURCE_DIR, o.out_dir);
      if (std::system(cmd.c_str()) != 0)
        fmt::print(stderr, "mpmx: plotting failed (the run's tables are complete): {}\n", cmd);
    }
  }
  if (!failure.empty()) throw RunError(failure);
  return r;
}

}  // namespace mpmx::mpm
