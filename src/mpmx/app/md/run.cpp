#include "mpmx/app/md/run.hpp"
#include "mpmx/app/md/elastic_record.hpp"
#include "mpmx/app/md/ensemble_averages.hpp"

#include <chrono>
#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/app/md/jet_run.hpp"
#include "mpmx/app/md/rod_run.hpp"
#include "mpmx/app/reported_quantities.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/run_record.hpp"
#include "mpmx/md/bar.hpp"
#include "mpmx/md/hugoniot.hpp"
#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/md/particles.hpp"
#include "mpmx/md/system.hpp"
#include "mpmx/particles/oriented_lattice.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::app::md {

namespace {

// md_run's payload: 2 with the input files' digests after the deck's text (every kind's);
// 3 with a box's whole thermostat and barostat state (kT, the Hugoniot's reference) and
// the Hugoniot's sums.
constexpr std::uint32_t kMdCheckpointVersion = 3;

// Advances in chunks an int holds (System::advance counts steps in int).
void advance_steps(System& s, std::int64_t steps, const Mat3& gradient, double dt) {
  for (std::int64_t done = 0; done < steps;) {
    const int chunk = static_cast<int>(std::min<std::int64_t>(steps - done, INT_MAX));
    s.advance(chunk, gradient, dt);
    done += chunk;
  }
}

// The message of a run the physics stopped, or "" while every figure a thermo row and
// run.json report is finite.
std::string non_finite_state(const System& s) {
  const double n = static_cast<double>(s.atoms().size());
  const Mat3 st = s.stress_gpa();
  const auto& b = s.box();
  return first_non_finite(s.step(), s.time(), "ps",
                          {{"the potential energy (eV/atom)", s.potential_energy() / n},
                           {"the kinetic energy (eV/atom)", s.kinetic_energy() / n},
                           {"the temperature (K)", s.temperature()},
                           {"stress xx (GPa)", st[0]},
                           {"stress yy (GPa)", st[4]},
                           {"stress zz (GPa)", st[8]},
                           {"stress xy (GPa)", st[1]},
                           {"stress xz (GPa)", st[2]},
                           {"stress yz (GPa)", st[5]},
                           {"the box length x (A)", b.lx},
                           {"the box length y (A)", b.ly},
                           {"the box length z (A)", b.lz}});
}

// nphug: the shocked state's sums over the thermo rows of the run's second half (their
// means are run.json's), carried in the checkpoint so a resumed run averages every row.
struct HugoniotSums {
  double v = 0, p = 0, t = 0;  // A^3, GPa along the shock axis, K
  std::int64_t rows = 0;
  void add(const System& s, int axis) {
    v += s.box().volume(), p -= s.stress_gpa()[4 * axis], t += s.temperature();
    ++rows;
  }
  void save(CheckpointOut& out) const {
    out.numbers({v, p, t});
    out.integer(rows);
  }
  static HugoniotSums load(CheckpointIn& in) {
    const long long at = in.offset();
    const auto sums = in.numbers();
    if (sums.size() != 3) throw in.refuse(at, fmt::format("the Hugoniot's sums: {} numbers, expected 3", sums.size()));
    HugoniotSums h{sums[0], sums[1], sums[2], in.integer()};
    if (h.rows < 0) throw in.refuse(at, fmt::format("the Hugoniot's sums: {} rows", h.rows));
    return h;
  }
};

toml::array matrix(const Mat3& m) {
  toml::array rows;
  for (int r = 0; r < 3; ++r) rows.push_back(toml::array{m[3 * r], m[3 * r + 1], m[3 * r + 2]});
  return rows;
}

// Energy per atom of the perfect lattice for each lattice constant (M1, fig. 7.2).
toml::table lattice_scan(const MdConfig& c, const Potential& pot) {
  toml::array as, es;
  double best_a = 0, best_e = 1e300;
  for (int k = 0; k < c.scan_points; ++k) {
    const double a = c.scan_from + (c.scan_to - c.scan_from) * k / (c.scan_points - 1);
    particles::LatticeSpec spec = c.lattice;
    spec.constant = a;
    System s(particles::oriented_crystal(spec, c.cells), pot, c.options);
    const double e = s.potential_energy() / static_cast<double>(s.atoms().size());
    as.push_back(a);
    es.push_back(e);
    if (e < best_e) best_e = e, best_a = a;
  }
  return toml::table{{"lattice_constant", as}, {"energy_per_atom", es},
                     {"minimum_lattice_constant", best_a}, {"minimum_energy_per_atom", best_e}};
}

// Direct-MD bar: slab stress over time in bar_stress.csv (long format).
// Returns "" or, when the state went non-finite, why the run stopped.
std::string run_bar(const MdConfig& c, const Potential& pot, const std::string& out_dir, MdRunSummary& r,
                    toml::table& rec, RunControl& control) {
  namespace fs = std::filesystem;
  Bar bar(c.bar_config, pot, c.options);
  if (control.resuming()) resume_md(control, bar.system(), c.steps);
  fs::create_directories(out_dir);  // only once the bar is built: a bad deck leaves nothing
  std::ofstream& csv =
      control.tables().open("bar_stress.csv", "step,time_ps,bin,x_A,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,sxz_GPa,syz_GPa\n");
  auto rows = [&] {
    const auto s = bar.slab_stress_gpa();
    const auto x = bar.slab_centres();
    for (std::size_t b = 0; b < s.size(); ++b)
      csv << fmt::format("{},{:.6f},{},{:.6g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n", bar.system().step(),
                         bar.system().time(), b, x[b], s[b][0], s[b][4], s[b][8], s[b][1], s[b][2], s[b][5]);
  };
  if (!control.resuming()) rows();
  const auto t0 = std::chrono::steady_clock::now();
  const std::int64_t first = bar.system().step();
  std::string stopped;
  for (std::int64_t done = first; done < c.steps;) {
    const std::int64_t chunk = std::min<std::int64_t>(c.bar_every, c.steps - done);
    bar.advance(static_cast<int>(chunk), c.dt);  // bar_every <= INT_MAX (config)
    done += chunk;
    rows();
    stopped = non_finite_state(bar.system());
    if (!stopped.empty()) break;
    if (done < c.steps && stop_md_at(control, bar.system(), {})) break;
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const System& s = bar.system();
  const double n = static_cast<double>(s.atoms().size());
  r.atoms = static_cast<long>(n);
  r.steps = static_cast<long>(s.step());
  r.steps_now = static_cast<long>(s.step() - first);
  r.atom_steps_per_second = secs > 0 ? n * static_cast<double>(s.step() - first) / secs : 0.0;
  r.potential_energy_per_atom = s.potential_energy() / n;
  r.stress_gpa = s.stress_gpa();
  r.step = s.step(), r.last_step = c.steps;
  rec.insert("bar", toml::table{{"wall_lo", s.walls().lo}, {"wall_hi", s.walls().hi},
                                {"bins", c.bar_config.bins}, {"stress_csv", "bar_stress.csv"}});
  return stopped;
}

// The keys every md run.json has; `extra` adds the run's own, then run.json is written
// atomically, valid JSON even when the state went non-finite. `stopped`: why the physics
// stopped the run ("" when it completed); an interrupted run names its checkpoint.
void write_record(const MdConfig& c, const Potential& pot, const toml::table& deck_echo,
                  const MdRunSummary& r, toml::table extra, const std::string& out_dir,
                  const std::string& stopped, RunControl& control) {
  const char* status = !stopped.empty() ? "stopped" : control.interrupted() ? "interrupted" : "completed";
  toml::table rec{{"version", MPMX_VERSION},
                  {"command", "md"},
                  {"case", c.id},
                  {"status", status},
                  {"deck_file", c.deck_file},
                  {"deck", deck_echo},
                  {"potential", pot.describe()},
                  {"atoms", static_cast<std::int64_t>(r.atoms)},
                  {"steps", static_cast<std::int64_t>(r.steps)},
                  {"dt_ps", c.dt},
                  {"wall_seconds", r.wall_seconds},
                  {"atom_steps_per_second", r.atom_steps_per_second},
                  {"threads", c.options.threaded ? c.options.threads : 1},
                  {"potential_energy_per_atom", r.potential_energy_per_atom},
                  {"stress_gpa", matrix(r.stress_gpa)}};
  if (!stopped.empty()) rec.insert("error", stopped);
  if (control.interrupted()) rec.insert("checkpoint", control.shown_checkpoint());
  for (auto&& [k, v] : extra) rec.insert_or_assign(k, std::move(v));
  io::write_file_atomic((std::filesystem::path(out_dir) / "run.json").string(), io::json_text(rec));
  if (stopped.empty() && !control.interrupted()) control.finished();
  if (!stopped.empty()) throw RunError(fmt::format("{} (partial results in {})", stopped, out_dir));
}

}  // namespace

toml::array tile_lengths(particles::LatticeSpec lattice, double constant) {
  lattice.constant = constant;
  const particles::TilePlanes t = particles::tile_planes(lattice);
  return toml::array{t.length[0], t.length[1], t.length[2]};
}

MdRunSummary run_md(const MdConfig& c, const std::string& out_dir, const toml::table& deck_echo,
                    const RunControlOptions& o) {
  namespace fs = std::filesystem;
  const auto t0 = std::chrono::steady_clock::now();
  RunControl control(out_dir, "md_run", deck_echo, o, kMdCheckpointVersion);
  const Potential pot(c.potential);
  if (c.bar || c.jet || c.rod) {
    MdRunSummary r;
    toml::table rec;
    const std::string stopped = c.bar   ? run_bar(c, pot, out_dir, r, rec, control)
                                : c.jet ? run_jet(c, pot, out_dir, r, rec, control, o.quiet)
                                        : run_rod(c, pot, out_dir, r, rec, control, o.quiet);
    r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.interrupted = control.interrupted();
    write_record(c, pot, deck_echo, r, std::move(rec), out_dir, stopped, control);
    return r;
  }
  System sys(particles::oriented_crystal(c.lattice, c.cells, c.strain_x), pot, c.options);
  const std::int64_t last_step = c.relax_steps + c.steps;
  // nvt, npt, nph, nphug: the thermostat and barostat, built once the atoms are placed
  // (nph's kT and nphug's reference are the box's then); on --resume, from the
  // checkpoint's state alone, as are the Hugoniot's sums.
  std::optional<NoseHoover> nh;
  HugoniotSums hug;
  if (control.resuming()) {
    resume_md_with(control, sys, last_step, [&](CheckpointIn& in) {
      const long long at = in.offset();
      const auto state = in.numbers();
      const std::size_t want = c.ensemble == "nve" ? 0 : NoseHoover::state_size(c.nose_hoover);
      if (state.size() != want)
        throw in.refuse(at, fmt::format("the thermostat and barostat: {} numbers, the deck's ensemble \"{}\" has {}",
                                        state.size(), c.ensemble, want));
      try {
        if (want > 0) nh.emplace(c.nose_hoover, sys.atoms().size(), state);
      } catch (const InputError& e) {
        throw in.refuse(at, e.what());
      }
      hug = HugoniotSums::load(in);
    });
  } else {
    if (c.temperature > 0) sys.thermalize(c.temperature, c.seed, 0);
    if (c.relax_steps > 0) advance_steps(sys, c.relax_steps, Mat3{}, c.dt);  // section 6.2
    if (c.streaming) sys.add_streaming_velocity(c.velocity_gradient);
    if (c.ensemble != "nve") nh.emplace(c.nose_hoover, sys);
  }
  // Only now, with the potential read and the system built: a bad deck or potential
  // leaves no output folder behind.
  fs::create_directories(out_dir);
  const double n = static_cast<double>(sys.atoms().size());
  std::string stopped;

  std::ofstream& csv = control.tables().open(
      "thermo.csv",
      "step,time_ps,pe_per_atom_eV,ke_per_atom_eV,etotal_per_atom_eV,temperature_K,"
      "sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,sxz_GPa,syz_GPa,lx_A,ly_A,lz_A\n");
  auto row = [&] {
    const Mat3 s = sys.stress_gpa();
    const double pe = sys.potential_energy() / n, ke = sys.kinetic_energy() / n;
    stopped = non_finite_state(sys);
    csv << fmt::format("{},{:.6f},{:.12g},{:.12g},{:.12g},{:.6g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.12g},{:.12g},{:.12g}\n",
                       sys.step(), sys.time(), pe, ke, pe + ke, sys.temperature(), s[0], s[4], s[8], s[1], s[2],
                       s[5], sys.box().lx, sys.box().ly, sys.box().lz);
  };
  std::ofstream* dump = c.dump_every > 0 ? &control.tables().open("dump.lammpstrj") : nullptr;
  if (!control.resuming()) {
    row();
    if (dump) write_dump_frame(*dump, sys, c.dump_fields, sys.options().threads);
  }
  std::int64_t done = sys.step() - c.relax_steps;
  Progress progress("md", c.steps, o.quiet, done);
  progress.show_rate(n, "atom-steps");
  const std::int64_t first = done;
  const auto run_start = std::chrono::steady_clock::now();
  const int axis = c.nose_hoover.axes[0] ? 0 : c.nose_hoover.axes[1] ? 1 : 2;
  while (done < c.steps) {
    const std::int64_t chunk = std::min<std::int64_t>(c.thermo - sys.step() % c.thermo, c.steps - done);
    if (nh) sys.advance_coupled(static_cast<int>(chunk), c.dt, *nh);
    else sys.advance(static_cast<int>(chunk), c.velocity_gradient, c.dt);
    done += chunk;
    if (sys.step() % c.thermo == 0 || done == c.steps) {
      row();
      if (c.nose_hoover.hugoniot && 2 * done > c.steps) hug.add(sys, axis);
    }
    if (!stopped.empty()) break;
    if (dump && sys.step() % c.dump_every == 0) write_dump_frame(*dump, sys, c.dump_fields, sys.options().threads);
    progress.update(done);
    if (done < c.steps && stop_md_with(control, sys, [&](CheckpointOut& out) {
          out.numbers(nh ? nh->state() : std::vector<double>{});
          hug.save(out);
        }))
      break;
  }
  const auto t1 = std::chrono::steady_clock::now();
  progress.finish(done);

  MdRunSummary r;
  r.atoms = static_cast<long>(n);
  const std::int64_t run_steps = sys.step() - c.relax_steps;  // fewer when stopped
  r.steps = static_cast<long>(run_steps);
  r.steps_now = static_cast<long>(done - first);
  r.wall_seconds = std::chrono::duration<double>(t1 - t0).count();
  const double run_seconds = std::chrono::duration<double>(t1 - run_start).count();
  r.atom_steps_per_second = run_seconds > 0 ? n * static_cast<double>(done - first) / run_seconds : 0.0;
  r.potential_energy_per_atom = sys.potential_energy() / n;
  r.stress_gpa = sys.stress_gpa();
  r.interrupted = control.interrupted();
  r.step = sys.step(), r.last_step = last_step;

  toml::table rec;
  rec.insert("relax_steps", static_cast<std::int64_t>(c.relax_steps));
  rec.insert("ensemble", c.ensemble);
  if (nh && c.nose_hoover.hugoniot && hug.rows > 0) {
    const double v = hug.v / hug.rows, p = hug.p / hug.rows, v0 = nh->v0();
    const double p0 = nh->p0() * units::eV_per_A3_in_GPa;
    const HugoniotPoint jump = jump_conditions(sys, v0, p0, v, p);
    toml::table h{{"shock_axis", std::string(1, static_cast<char>('x' + axis))},
                  {"reference_volume_A3", v0},
                  {"reference_pressure_GPa", p0},
                  {"reference_energy_eV", nh->e0()},
                  {"reference_density_g_cm3", jump.rho0},
                  {"rows_averaged", hug.rows},
                  {"volume_ratio", v / v0},
                  {"pressure_GPa", p},
                  {"temperature_K", hug.t / hug.rows},
                  {"shock_speed_km_s", jump.us},
                  {"particle_velocity_km_s", jump.up}};
    rec.insert("hugoniot", h);
  }
  {  // the lattice constant the box now holds along each axis: its edge over its tiles
    const particles::LatticeTile tile = particles::lattice_tile(c.lattice);
    const double l[3] = {sys.box().lx, sys.box().ly, sys.box().lz};
    toml::array a;
    for (int d = 0; d < 3; ++d) a.push_back(c.lattice.constant * l[d] / (c.cells[d] * tile.length[d]));
    rec.insert("lattice_constant_A", a);
    // A thermostat's or barostat's state is a mean, not the last row's numbers.
    if (c.ensemble != "nve") {
      csv.flush();
      std::array<double, 3> per_length{};
      for (int d = 0; d < 3; ++d) per_length[d] = c.lattice.constant / (c.cells[d] * tile.length[d]);
      toml::table avg = ensemble_averages((std::filesystem::path(out_dir) / "thermo.csv").string(),
                                          c.relax_steps + c.steps / 2, per_length);
      auto mean = [&](const char* k) { return avg[k]["mean"].value_or(std::nan("")); };
      auto error = [&](const char* k) { return avg[k]["standard_error"].value_or(std::nan("")); };
      if (avg.contains("temperature_K"))
        r.notes.push_back(fmt::format(
            "averages over the run's second half ({} rows; run.json's averages): T {:.2f} +- {:.2g} K, P {:.4f} +- "
            "{:.2g} GPa, lattice constant {:.6f} +- {:.2g}, {:.6f}, {:.6f} A (x, y, z)",
            avg["rows"].value_or(std::int64_t{0}), mean("temperature_K"), error("temperature_K"), mean("pressure_GPa"),
            error("pressure_GPa"), mean("lattice_constant_x_A"), error("lattice_constant_x_A"),
            mean("lattice_constant_y_A"), mean("lattice_constant_z_A")));
      rec.insert("averages", std::move(avg));
    }
  }
  rec.insert("run_seconds", run_seconds);
  rec.insert("kinetic_energy_per_atom", sys.kinetic_energy() / n);
  rec.insert("temperature_K", sys.temperature());
  rec.insert("box", toml::table{{"lx", sys.box().lx}, {"ly", sys.box().ly}, {"lz", sys.box().lz},
                                {"xy", sys.box().xy}, {"xz", sys.box().xz}, {"yz", sys.box().yz}});
  rec.insert("neighbor_builds", sys.neighbor_builds());
  rec.insert("precision", c.options.mixed_precision ? "mixed" : "double");
  if (c.scan_points > 0 && stopped.empty() && !r.interrupted) rec.insert("scan", lattice_scan(c, pot));
  if (c.elastic && stopped.empty() && !r.interrupted) {
    ElasticRecord e = elastic_record(c, pot);
    rec.insert("elastic", std::move(e.table));
    r.notes.push_back(std::move(e.summary));
  }
  write_record(c, pot, deck_echo, r, std::move(rec), out_dir, stopped, control);
  return r;
}

}  // namespace mpmx::app::md
