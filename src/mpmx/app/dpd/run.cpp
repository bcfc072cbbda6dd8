#include "mpmx/app/dpd/run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mpmx/app/dpd/dump.hpp"
#include "mpmx/app/dpd/preflight.hpp"
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

class Thermo {
 public:
  Thermo(const std::string& path, const System& s) : out_(path) {
    out_ << "phase,step,time_ps,pe_eV,ke_eV,internal_eV,etotal_eV,temperature_K,internal_temperature_K,"
            "px_amu_A_per_ps,py_amu_A_per_ps,pz_amu_A_per_ps,pressure_GPa,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,"
            "sxz_GPa,syz_GPa";
    for (const auto& g : s.groups()) out_ << fmt::format(",{0}_fx_eV_per_A,{0}_fy_eV_per_A,{0}_fz_eV_per_A", g.name);
    out_ << "\n";
  }
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
  }

 private:
  std::ofstream out_;
};

toml::array vec(const particles::Vec3& v) { return toml::array{v[0], v[1], v[2]}; }

// What a run writes as it goes: thermo rows, dump frames (with their CNA structure when
// asked), the analysis records, and the run phase's rows the energy drift and the mean
// temperature are taken from.
class RunLog {
 public:
  RunLog(const DpdConfig& c, System& sys, const std::string& out_dir, bool quiet)
      : c_(c), sys_(sys), thermo_((std::filesystem::path(out_dir) / "thermo.csv").string(), sys), quiet_(quiet) {
    if (c.dump_every > 0) dump_.open(std::filesystem::path(out_dir) / "dump.lammpstrj");
  }

  // One phase of `steps` steps with thermo rows and progress; `run`: the run itself (its
  // rows counted, frames dumped, records taken), not the equilibration. Returns its seconds.
  double phase(const char* name, std::int64_t steps, const Berendsen* b, bool run) {
    thermo_.row(name, sys_);
    if (run && c_.dump_every > 0) frame();
    Progress progress(fmt::format("dpd {}", name), steps, quiet_);
    progress.show_rate(static_cast<double>(sys_.particles().size()), "particle-steps");
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t stride = run && recorder ? c_.analysis.every : c_.thermo;
    for (std::int64_t done = 0; done < steps;) {
      const std::int64_t chunk = std::min<std::int64_t>(stride, steps - done);
      sys_.advance(static_cast<int>(chunk), c_.dt, b);
      done += chunk;
      if (run && recorder) recorder->record(sys_);
      if (done % c_.thermo != 0 && done != steps) continue;
      thermo_.row(name, sys_);
      if (run) {
        tsum += sys_.temperature(), ++tcount;
        add_row();
      }
      if (run && c_.dump_every > 0 && done % c_.dump_every == 0) frame();
      progress.update(done);
    }
    progress.finish();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // The run's row of the system as it stands (its start, then every thermo row).
  void add_row() {
    row_step.push_back(static_cast<double>(sys_.step()));
    row_energy.push_back(sys_.total_energy());
    row_kinetic.push_back(sys_.kinetic_energy());
  }

  std::unique_ptr<Recorder> recorder;  // the run's analysis records
  double tsum = 0;  // kinetic temperature summed over the run's thermo rows
  long tcount = 0;
  std::vector<double> row_step, row_energy, row_kinetic;  // the run's rows, for the drift

 private:
  void frame() {
    if (c_.analysis.cna_lattice > 0) {
      structure_ = common_neighbour_analysis(sys_.particles(), sys_.domain(), c_.analysis.cna_lattice);
      write_lammps_dump(dump_, sys_.step(), sys_.particles(), sys_.domain(), &structure_);
    } else {
      write_lammps_dump(dump_, sys_.step(), sys_.particles(), sys_.domain());
    }
  }

  const DpdConfig& c_;
  System& sys_;
  Thermo thermo_;
  std::ofstream dump_;
  std::vector<std::uint8_t> structure_;
  bool quiet_;
};

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
double energy_drift(const RunLog& log, bool energy_conserving) {
  const std::vector<double>& row_step = log.row_step;
  const std::vector<double>& row_energy = log.row_energy;
  const std::vector<double>& row_kinetic = log.row_kinetic;
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
                       int threads, double run_seconds, const RunStart& at) {
  const double e0 = at.energy, k0 = at.kinetic;
  const particles::Vec3& p0 = at.momentum;
  const std::int64_t step0 = at.step;
  const particles::Vec3 p1 = sys.momentum();
  toml::table rec{{"version", MPMX_VERSION},
                  {"command", "dpd"},
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
  return rec;
}

}  // namespace

DpdRunSummary run_dpd(const DpdConfig& c, const std::string& out_dir, const toml::table& deck_echo, int threads,
                      bool quiet, const MoverFactory& make_mover) {
  namespace fs = std::filesystem;
  fs::create_directories(out_dir);
  const auto t0 = std::chrono::steady_clock::now();
  System sys = build_system(c, threads);
  const double n = static_cast<double>(sys.particles().size());
  RunLog log(c, sys, out_dir, quiet);

  if (c.equilibrate && c.equilibrate_steps > 0) log.phase("equilibrate", c.equilibrate_steps, &c.berendsen, false);
  // The run: rigid groups at their velocities, energy and momentum from here.
  DpdRunSummary r;
  start_run(c, sys);
  std::unique_ptr<Mover> mover;
  if (make_mover) {
    mover = make_mover(sys);
    sys.set_mover(mover.get());
  }
  double fcc_start = -1;
  auto fcc_now = [&] { return interior_fcc_fraction(sys.particles(), sys.domain(), c.analysis.cna_lattice); };
  if (c.analysis.cna_lattice > 0) fcc_start = fcc_now();
  if (c.analysis.records()) log.recorder = std::make_unique<Recorder>(c.analysis, sys);
  const RunStart start{sys.total_energy(), sys.kinetic_energy(), sys.momentum(), sys.step()};
  log.add_row();
  const double run_seconds = log.phase("run", c.steps, nullptr, true);
  const auto t1 = std::chrono::steady_clock::now();

  r.particles = static_cast<long>(n);
  r.steps = static_cast<long>(c.steps);
  r.wall_seconds = std::chrono::duration<double>(t1 - t0).count();
  r.particle_steps_per_second = run_seconds > 0 ? n * c.steps / run_seconds : 0.0;
  r.energy_drift = energy_drift(log, c.params.energy_conserving);
  r.temperature = log.tcount > 0 ? log.tsum / log.tcount : sys.temperature();

  toml::table rec = run_record(c, sys, r, deck_echo, threads, run_seconds, start);
  toml::table model{{"name", c.continuum.on ? "dpd_mpm_concurrent" : mover ? "dpd_mpm_grid" : "dpd_only"}};
  if (mover) mover->report(model);
  rec.insert("model", model);
  if (log.recorder) {
    log.recorder->write(out_dir);
    rec.insert("analysis", log.recorder->summary());
    r.wave_speed = log.recorder->wave_speed();
    r.initial_slope = log.recorder->initial_slope();
    r.peak_stress = log.recorder->peak_stress();
    r.peak_strain = log.recorder->peak_strain();
  }
  if (c.analysis.cna_lattice > 0) {
    r.fcc_start = fcc_start;
    r.fcc_end = fcc_now();
    rec.insert("cna", toml::table{{"lattice_constant_A", c.analysis.cna_lattice},
                                  {"interior_fcc_fraction_start", r.fcc_start},
                                  {"interior_fcc_fraction_end", r.fcc_end}});
  }
  std::ostringstream os;
  os << toml::json_formatter{rec} << '\n';
  io::write_file_atomic((fs::path(out_dir) / "run.json").string(), os.str());
  return r;
}

}  // namespace mpmx::app::dpd
