#include "mpmx/app/dpd/run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mpmx/app/dpd/dump.hpp"
#include "mpmx/app/dpd/preflight.hpp"
#include "mpmx/app/reported_quantities.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/dpd/cna.hpp"
#include "mpmx/dpd/setup.hpp"
#include "mpmx/io/run_record.hpp"

namespace mpmx::app::dpd {

System build_system(const DpdConfig& c, int threads) {
  Particles all;
  std::vector<RigidGroup> groups;
  std::int64_t next_id = 1;
  for (std::size_t b = 0; b < c.blocks.size(); ++b) {
    const BlockSpec& s = c.blocks[b];
    Particles p = s.fcc ? fcc_block(s.cells, s.constant, s.origin, s.mass, 0, next_id)
                        : random_block(s.count, s.size, s.origin, s.mass, 0, next_id, block_seed(c, b));
    next_id += static_cast<std::int64_t>(p.size());
    if (!s.group.empty()) {
      groups.push_back({s.group, s.velocity});
      for (auto& g : p.group) g = static_cast<int>(groups.size()) - 1;
    }
    append(all, p);
  }
  for (const RegionGroupSpec& r : c.regions) {
    groups.push_back({r.name, r.velocity});
    const int g = static_cast<int>(groups.size()) - 1;
    long n = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      const double x[3] = {all.x[i], all.y[i], all.z[i]};
      bool in = !all.rigid(i);
      for (int d = 0; d < 3; ++d) in = in && x[d] >= r.lo[d] && x[d] < r.hi[d];
      if (in) all.group[i] = g, ++n;
    }
    if (n == 0) throw InputError(fmt::format("rigid group \"{}\": its region holds no particle", r.name));
  }
  maxwell_velocities(all, c.initial_temperature, c.params.seed);
  // Mobile blocks with a velocity move as a whole on top of the thermal motion.
  {
    std::size_t i = 0;
    for (const BlockSpec& s : c.blocks) {
      const std::size_t n = s.fcc ? 4ul * s.cells[0] * s.cells[1] * s.cells[2] : static_cast<std::size_t>(s.count);
      if (s.group.empty())
        for (std::size_t k = i; k < i + n; ++k)
          all.vx[k] += s.velocity[0], all.vy[k] += s.velocity[1], all.vz[k] += s.velocity[2];
      i += n;
    }
  }
  if (c.params.energy_conserving)
    for (auto& u : all.u) u = c.params.heat_capacity * c.initial_temperature;
  if (c.continuum.on) groups.push_back({multiscale::kContinuumGroup, {0, 0, 0}, true});
  std::vector<RigidGroup> at_rest = groups;
  for (auto& g : at_rest) g.velocity = {0, 0, 0};
  SystemOptions opt;
  opt.skin = c.skin;
  opt.threads = threads;
  return System(std::move(all), c.domain, c.potential, c.params, opt, std::move(at_rest));
}

namespace {

// thermo.csv: a row per thermo interval of each phase.
class Thermo {
 public:
  Thermo(RunTables& tables, const System& s) : out_(tables.open("thermo.csv", header(s))) {}
  void row(const char* phase, const System& s) {
    const auto st = s.stress_gpa();
    const auto m = s.momentum();
    out_ << fmt::format("{},{},{:.6f},{:.15g},{:.15g},{:.15g},{:.15g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},"
                        "{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}",
                        phase, s.step(), s.time(), s.potential_energy(), s.kinetic_energy(), s.internal_energy(),
                        s.total_energy(), s.temperature(), s.internal_temperature(), m[0], m[1], m[2],
                        s.pressure_gpa(), st[0], st[4], st[8], st[1], st[2], st[5]);
    for (std::size_t g = 0; g < s.groups().size(); ++g) {
      const auto f = s.group_force(static_cast<int>(g));
      out_ << fmt::format(",{:.10g},{:.10g},{:.10g}", f[0], f[1], f[2]);
    }
    out_ << "\n";
    // The row is written as it is (the last of a stopped run), then the run stops.
    const std::string why = first_non_finite(
        s.step(), s.time(), "ps",
        {{"the potential energy (eV)", s.potential_energy()}, {"the kinetic energy (eV)", s.kinetic_energy()},
         {"the internal energy (eV)", s.internal_energy()}, {"the temperature (K)", s.temperature()},
         {"the internal temperature (K)", s.internal_temperature()}, {"the pressure (GPa)", s.pressure_gpa()},
         {"stress xx (GPa)", st[0]}, {"stress yy (GPa)", st[4]}, {"stress zz (GPa)", st[8]},
         {"stress xy (GPa)", st[1]}, {"stress xz (GPa)", st[2]}, {"stress yz (GPa)", st[5]}});
    if (!why.empty()) throw RunError("DPD " + why);
  }

 private:
  static std::string header(const System& s) {
    std::string h =
        "phase,step,time_ps,pe_eV,ke_eV,internal_eV,etotal_eV,temperature_K,internal_temperature_K,"
        "px_amu_A_per_ps,py_amu_A_per_ps,pz_amu_A_per_ps,pressure_GPa,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,"
        "sxz_GPa,syz_GPa";
    for (const auto& g : s.groups()) h += fmt::format(",{0}_fx_eV_per_A,{0}_fy_eV_per_A,{0}_fz_eV_per_A", g.name);
    return h + "\n";
  }
  std::ofstream& out_;
};

toml::array vec(const particles::Vec3& v) { return toml::array{v[0], v[1], v[2]}; }

// The run's start after the equilibration: rigid groups at their velocities, in
// build_system's order (blocks, then regions), the free ones then moving by their forces;
// a concurrent run's continuum points, the equilibrated particles of its region.
void start_run(const DpdConfig& c, System& sys) {
  for (const BlockSpec& s : c.blocks) {
    if (s.group.empty()) continue;
    const int g = sys.group_index(s.group);
    sys.set_group_velocity(g, c.still ? particles::Vec3{} : s.velocity);
    if (s.free) sys.release_group(g);
  }
  for (const RegionGroupSpec& s : c.regions)
    sys.set_group_velocity(sys.group_index(s.name), c.still ? particles::Vec3{} : s.velocity);
  if (c.continuum.on) {
    std::vector<std::int64_t> ids;
    const Particles& p = sys.particles();
    for (std::size_t i = 0; i < p.size(); ++i)
      if (!p.rigid(i) && p.x[i] >= c.continuum.lo && p.x[i] < c.continuum.hi) ids.push_back(p.id[i]);
    if (ids.empty())
      throw InputError(fmt::format("continuum.x = [{}, {}]: no mobile particle lies there at the run's start",
                                   c.continuum.lo, c.continuum.hi));
    sys.make_external(sys.group_index(multiscale::kContinuumGroup), ids);
  }
}

// Drift: least-squares slope of the total energy over the run's rows, per 1000 steps,
// over the mean kinetic energy (the rows' scatter is velocity Verlet's O(dt^2) wobble);
// 0 unless DPDE.
double energy_drift(const std::vector<double>& row_step, const std::vector<double>& row_energy,
                    const std::vector<double>& row_kinetic, bool energy_conserving) {
  double slope = 0, mean_k = 0;
  if (row_step.size() >= 2) {
    const double m = static_cast<double>(row_step.size());
    double mx = 0, my = 0;
    for (std::size_t k = 0; k < row_step.size(); ++k) mx += row_step[k] / m, my += row_energy[k] / m, mean_k += row_kinetic[k] / m;
    double sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < row_step.size(); ++k)
      sxy += (row_step[k] - mx) * (row_energy[k] - my), sxx += (row_step[k] - mx) * (row_step[k] - mx);
    slope = sxx > 0 ? sxy / sxx : 0.0;
  }
  return (energy_conserving && mean_k > 0) ? slope * 1000 / mean_k : 0.0;
}

// The state at the run's start that run.json compares the end with.
struct RunStart {
  double energy = 0, kinetic = 0;
  particles::Vec3 momentum{};
  std::int64_t step = 0;
};

// run.json's figures of the run (the model, analysis and CNA are added after).
toml::table run_record(const DpdConfig& c, const System& sys, const DpdRunSummary& r, const toml::table& deck_echo,
                       int threads, double run_seconds, const RunStart& at, const RunControl& control) {
  const double e0 = at.energy, k0 = at.kinetic;
  const particles::Vec3& p0 = at.momentum;
  const std::int64_t step0 = at.step;
  const particles::Vec3 p1 = sys.momentum();
  toml::table rec{{"version", MPMX_VERSION},
                  {"command", "dpd"},
                  {"status", control.interrupted() ? "interrupted" : "completed"},
                  {"deck_file", c.deck_file},
                  {"deck", deck_echo},
                  {"case", c.id},
                  {"still", c.still},
                  {"potential", describe(c.potential)},
                  {"particles", static_cast<std::int64_t>(r.particles)},
                  {"steps", static_cast<std::int64_t>(r.steps)},
                  {"equilibrate_steps", static_cast<std::int64_t>(c.equilibrate ? c.equilibrate_steps : 0)},
                  {"dt_ps", c.dt},
                  {"threads", threads},
                  {"wall_seconds", r.wall_seconds},
                  {"run_seconds", run_seconds},
                  {"particle_steps_per_second", r.particle_steps_per_second},
                  {"neighbor_builds", sys.neighbor_builds()},
                  {"sweep_slabs", sys.sweep_slabs()},
                  {"integrator", c.params.integrator == Integrator::shardlow ? "shardlow" : "velocity_verlet"},
                  {"ensemble", c.params.energy_conserving ? "dpde" : "dpd"},
                  {"mean_temperature_K", r.temperature},
                  {"final",
                   toml::table{{"step", sys.step()},
                               {"potential_energy_eV", sys.potential_energy()},
                               {"kinetic_energy_eV", sys.kinetic_energy()},
                               {"internal_energy_eV", sys.internal_energy()},
                               {"temperature_K", sys.temperature()},
                               {"internal_temperature_K", sys.internal_temperature()},
                               {"pressure_GPa", sys.pressure_gpa()}}},
                  {"conservation",
                   toml::table{{"energy_start_eV", e0},
                               {"energy_end_eV", sys.total_energy()},
                               {"energy_drift_per_1000_steps_over_kinetic", r.energy_drift},
                               {"energy_change_over_kinetic", k0 > 0 ? (sys.total_energy() - e0) / k0 : 0.0},
                               {"momentum_start", vec(p0)},
                               {"momentum_end", vec(p1)},
                               {"from_step", step0}}}};
  if (control.interrupted()) rec.insert("checkpoint", control.shown_checkpoint());
  return rec;
}

// One DPD run: the equilibration and the run phases with their tables, and the checkpoint
// a Ctrl-C or SIGTERM (or --stop-after) writes at a record, which --resume reads back.
// The checkpoint (app/run_control.hpp; kind dpd_run, counted in particles) holds the
// phase, the system (dpd/checkpoint.cpp), and in the run phase the mover's state, the
// analysis records, the run's start and the thermo rows' sums.
class DpdRun {
 public:
  DpdRun(const DpdConfig& c, const std::string& dir, const toml::table& deck_echo, int threads,
         const RunControlOptions& o, const MoverFactory& make_mover)
      : c_(c), dir_(dir), deck_echo_(deck_echo), threads_(threads), make_mover_(make_mover),
        control_(dir, "dpd_run", deck_echo, o), sys_(build_system(c, threads)) {}

  DpdRunSummary run() {
    namespace fs = std::filesystem;
    const auto t0 = std::chrono::steady_clock::now();
    if (control_.resuming()) control_.resume(sys_.particles().size(), [&](CheckpointIn& in) { load(in); });
    fs::create_directories(dir_);
    thermo_.emplace(control_.tables(), sys_);
    if (c_.dump_every > 0) dump_ = &control_.tables().open("dump.lammpstrj");
    double run_seconds = 0;
    try {
      if (phase_ == kEquilibrate) {
        if (c_.equilibrate && c_.equilibrate_steps > 0) phase("equilibrate", c_.equilibrate_steps, &c_.berendsen);
        if (!control_.interrupted()) begin_run();
      }
      if (!control_.interrupted()) run_seconds = phase("run", c_.steps, nullptr);
    } catch (const RunError& e) {
      // Stopped by the physics: run.json says so and why, with the figures as they are.
      stopped_ = e.what();
    }
    return finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), run_seconds);
  }

 private:
  enum Phase : std::int64_t { kEquilibrate = 0, kRun = 1 };

  // The run's start: rigid groups at their velocities, the mover in place, the analysis's
  // reference, energy and momentum from here.
  void begin_run() {
    start_run(c_, sys_);
    if (make_mover_) {
      mover_ = make_mover_(sys_);
      sys_.set_mover(mover_.get());
    }
    if (c_.analysis.cna_lattice > 0) fcc_start_ = fcc_now();
    if (c_.analysis.records()) recorder_ = std::make_unique<Recorder>(c_.analysis, sys_);
    start_ = {sys_.total_energy(), sys_.kinetic_energy(), sys_.momentum(), sys_.step()};
    phase_ = kRun;
    add_row();
  }

  double fcc_now() const { return interior_fcc_fraction(sys_.particles(), sys_.domain(), c_.analysis.cna_lattice); }

  // One phase of `steps` steps with thermo rows and progress; in the run phase, the rows
  // counted, frames dumped and records taken. Stops at a record when asked to (the
  // checkpoint written). Returns its seconds in this process.
  double phase(const char* name, std::int64_t steps, const Berendsen* b) {
    const bool run = phase_ == kRun;
    const std::int64_t from = sys_.step() - (run ? start_.step : 0);
    if (run) run_from_ = from;
    if (from == 0) {
      thermo_->row(name, sys_);
      if (run && dump_) frame();
    }
    Progress progress(fmt::format("dpd {}", name), steps, control_.options().quiet, from);
    progress.show_rate(static_cast<double>(sys_.particles().size()), "particle-steps");
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t stride = run && recorder_ ? c_.analysis.every : c_.thermo;
    std::int64_t done = from;
    while (done < steps) {
      const std::int64_t chunk = std::min<std::int64_t>(stride, steps - done);
      sys_.advance(static_cast<int>(chunk), c_.dt, b);
      done += chunk;
      if (run && recorder_) recorder_->record(sys_);
      if (done % c_.thermo == 0 || done == steps) {
        thermo_->row(name, sys_);
        if (run) {
          tsum_ += sys_.temperature(), ++tcount_;
          add_row();
        }
        if (run && dump_ && done % c_.dump_every == 0) frame();
        progress.update(done);
      }
      if (done < steps && control_.stop_due(sys_.step())) {
        control_.checkpoint(sys_.particles().size(), [&](CheckpointOut& w) { save(w); });
        break;
      }
    }
    progress.finish(done);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // The run's row of the system as it stands (its start, then every thermo row).
  void add_row() {
    row_step_.push_back(static_cast<double>(sys_.step()));
    row_energy_.push_back(sys_.total_energy());
    row_kinetic_.push_back(sys_.kinetic_energy());
  }

  void frame() {
    if (c_.analysis.cna_lattice > 0) {
      structure_ = common_neighbour_analysis(sys_.particles(), sys_.domain(), c_.analysis.cna_lattice);
      write_lammps_dump(*dump_, sys_.step(), sys_.particles(), sys_.domain(), &structure_);
    } else {
      write_lammps_dump(*dump_, sys_.step(), sys_.particles(), sys_.domain());
    }
  }

  void save(CheckpointOut& w) const {
    w.integer(phase_);
    sys_.save(w.stream());
    if (phase_ != kRun) return;
    w.integer(mover_ ? 1 : 0);
    if (mover_) mover_->save(w.stream());
    w.integer(recorder_ ? 1 : 0);
    if (recorder_) recorder_->save(w);
    w.numbers({start_.energy, start_.kinetic, start_.momentum[0], start_.momentum[1], start_.momentum[2], fcc_start_,
               tsum_});
    w.integer(start_.step);
    w.integer(tcount_);
    for (const auto* v : {&row_step_, &row_energy_, &row_kinetic_}) w.numbers(*v);
  }

  // Every piece read aside and checked against the deck before the run takes it.
  void load(CheckpointIn& in) {
    const long long at_phase = in.offset();
    const std::int64_t phase = in.integer();
    if (phase != kEquilibrate && phase != kRun) throw in.refuse(at_phase, fmt::format("phase {}", phase));
    const long long at_sys = in.offset();
    try {
      sys_.load(in.stream());
    } catch (const InputError& e) {
      throw in.refuse(at_sys, fmt::format("the DPD system: {}", e.what()));
    }
    const std::int64_t last = (c_.equilibrate ? c_.equilibrate_steps : 0) + c_.steps;
    if (sys_.step() >= last)
      throw in.refuse(at_sys, fmt::format("step {} is at or past the deck's last step {}", sys_.step(), last));
    phase_ = static_cast<Phase>(phase);
    if (phase_ != kRun) return;
    const long long at_mover = in.offset();
    if ((in.integer() != 0) != static_cast<bool>(make_mover_))
      throw in.refuse(at_mover, "its DPD/MPM grid is not the deck's");
    if (make_mover_) {
      mover_ = make_mover_(sys_);
      sys_.set_mover(mover_.get());
      try {
        mover_->load(in.stream());
      } catch (const InputError& e) {
        throw in.refuse(at_mover, e.what());
      }
    }
    const long long at_rec = in.offset();
    if ((in.integer() != 0) != c_.analysis.records()) throw in.refuse(at_rec, "its analysis is not the deck's");
    if (c_.analysis.records()) recorder_ = std::make_unique<Recorder>(Recorder::load(c_.analysis, sys_, in));
    const long long at_start = in.offset();
    const auto k = in.numbers();
    if (k.size() != 7) throw in.refuse(at_start, "the run's start is not 7 numbers");
    start_ = {k[0], k[1], {k[2], k[3], k[4]}, in.integer()};
    fcc_start_ = k[5], tsum_ = k[6];
    tcount_ = in.integer();
    if (start_.step < 0 || start_.step > sys_.step() || tcount_ < 0)
      throw in.refuse(at_start, fmt::format("the run's start at step {} with {} rows", start_.step, tcount_));
    for (auto* v : {&row_step_, &row_energy_, &row_kinetic_}) *v = in.numbers();
  }

  DpdRunSummary finish(double wall_seconds, double run_seconds) {
    DpdRunSummary r;
    const double n = static_cast<double>(sys_.particles().size());
    const std::int64_t run_steps = phase_ == kRun ? sys_.step() - start_.step : 0;
    r.particles = static_cast<long>(n);
    r.steps = static_cast<long>(run_steps);
    r.wall_seconds = wall_seconds;
    r.particle_steps_per_second = run_seconds > 0 ? n * static_cast<double>(run_steps - run_from_) / run_seconds : 0.0;
    r.energy_drift = energy_drift(row_step_, row_energy_, row_kinetic_, c_.params.energy_conserving);
    r.temperature = tcount_ > 0 ? tsum_ / tcount_ : sys_.temperature();
    r.interrupted = control_.interrupted();
    r.step = sys_.step();
    r.last_step = (c_.equilibrate ? c_.equilibrate_steps : 0) + c_.steps;

    toml::table rec = run_record(c_, sys_, r, deck_echo_, threads_, run_seconds, start_, control_);
    toml::table model{{"name", c_.continuum.on ? "dpd_mpm_concurrent" : mover_ ? "dpd_mpm_grid" : "dpd_only"}};
    if (mover_) mover_->report(model);
    rec.insert("model", model);
    if (recorder_) {
      recorder_->write(dir_);
      rec.insert("analysis", recorder_->summary());
      r.wave_speed = recorder_->wave_speed();
      r.initial_slope = recorder_->initial_slope();
      r.peak_stress = recorder_->peak_stress();
      r.peak_strain = recorder_->peak_strain();
    }
    if (c_.analysis.cna_lattice > 0 && phase_ == kRun) {
      r.fcc_start = fcc_start_;
      r.fcc_end = fcc_now();
      rec.insert("cna", toml::table{{"lattice_constant_A", c_.analysis.cna_lattice},
                                    {"interior_fcc_fraction_start", r.fcc_start},
                                    {"interior_fcc_fraction_end", r.fcc_end}});
    }
    if (!stopped_.empty()) {
      rec.insert_or_assign("status", "stopped");
      rec.insert("error", stopped_);
    }
    std::ostringstream os;
    os << toml::json_formatter{rec} << '\n';
    io::write_file_atomic((std::filesystem::path(dir_) / "run.json").string(), os.str());
    if (!stopped_.empty()) throw RunError(fmt::format("{} (partial results in {})", stopped_, dir_));
    if (!r.interrupted) control_.finished();
    return r;
  }

  const DpdConfig& c_;
  std::string dir_;
  const toml::table& deck_echo_;
  int threads_;
  const MoverFactory& make_mover_;
  RunControl control_;
  System sys_;
  Phase phase_ = kEquilibrate;
  std::unique_ptr<Mover> mover_;
  std::unique_ptr<Recorder> recorder_;
  std::optional<Thermo> thermo_;
  std::ofstream* dump_ = nullptr;
  std::vector<std::uint8_t> structure_;
  RunStart start_;
  double fcc_start_ = -1;
  double tsum_ = 0;  // kinetic temperature summed over the run's thermo rows
  std::int64_t tcount_ = 0;
  std::int64_t run_from_ = 0;  // the run phase's steps before this process
  std::string stopped_;        // why the physics stopped the run ("" while it runs)
  std::vector<double> row_step_, row_energy_, row_kinetic_;  // the run's rows, for the drift
};

}  // namespace

DpdRunSummary run_dpd(const DpdConfig& c, const std::string& out_dir, const toml::table& deck_echo, int threads,
                      const RunControlOptions& o, const MoverFactory& make_mover) {
  return DpdRun(c, out_dir, deck_echo, threads, o, make_mover).run();
}

}  // namespace mpmx::app::dpd
