#include "mpmx/app/md/rod_run.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include <fmt/format.h>

#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/app/md/run.hpp"
#include "mpmx/app/reported_quantities.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/md/rod.hpp"

namespace mpmx::app::md {

namespace {

// Steps from `step` to the next multiple of k.
std::int64_t to_next(std::int64_t step, std::int64_t k) { return k - step % k; }

double flyer_vx(const System& s, std::int64_t flyer_atoms) {
  const Atoms& a = s.atoms();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.id[i] <= flyer_atoms) return a.vx[i];  // a rigid body: every atom has it
  return 0.0;
}

}  // namespace

std::string run_rod(const MdConfig& c, const Potential& pot, const std::string& out_dir, MdRunSummary& r,
                    toml::table& rec, RunControl& control, bool quiet) {
  namespace fs = std::filesystem;
  RodGeometry geo;
  System sys = build_rod(c.rod_config, pot, c.options, &geo);
  const std::int64_t eq = c.rod_equilibrate_steps, last = eq + c.steps, nf = geo.flyer_atoms;
  std::vector<double> x;  // the deck's frame
  auto frame = [&] {
    const Atoms& a = sys.atoms();
    x.resize(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) x[i] = a.x[i] - geo.offset[0];
    return TrackFrame{sys.time(), a.id, x, a.vx};
  };
  std::optional<RegionTracks> tracks;
  auto release = [&] {  // the run's start: the flyer sent, the tracks' reference taken
    sys.release_rigid({c.still ? 0.0 : c.rod_velocity, 0.0, 0.0});
    tracks.emplace(c.tracks, frame(), [&](std::size_t i) { return sys.atoms().id[i] > nf; });
  };
  if (control.resuming()) {
    resume_md_with(control, sys, last, [&](CheckpointIn& in) {
      if (in.integer() != 0) tracks.emplace(RegionTracks::load(c.tracks, in, "the rod's tracks"));
    });
    if (tracks) sys.set_rigid(nf, true);
  }
  fs::create_directories(out_dir);  // only once the sample is built
  RunTables& tables = control.tables();
  std::ofstream& thermo = tables.open("thermo.csv",
                                      "step,time_ps,phase,pe_per_atom_eV,ke_per_atom_eV,etotal_per_atom_eV,"
                                      "target_temperature_K,flyer_vx_A_per_ps\n");
  std::ofstream* dump = c.dump_every > 0 ? &tables.open("dump.lammpstrj") : nullptr;
  const double n = static_cast<double>(sys.atoms().size());
  std::string stopped;
  auto row = [&] {
    const double pe = sys.potential_energy() / n, ke = sys.kinetic_energy() / n;
    thermo << fmt::format("{},{:.6f},{},{:.12g},{:.12g},{:.12g},{:.6g},{:.8g}\n", sys.step(), sys.time(),
                          tracks ? "run" : "equilibrate", pe, ke, pe + ke, sys.temperature_after(nf),
                          flyer_vx(sys, nf));
    thermo.flush();  // a long run can be followed as it goes
    stopped = first_non_finite(sys.step(), sys.time(), "ps",
                               {{"the potential energy (eV/atom)", pe},
                                {"the kinetic energy (eV/atom)", ke},
                                {"the target's temperature (K)", sys.temperature_after(nf)},
                                {"the flyer's velocity (A/ps)", flyer_vx(sys, nf)}});
  };
  auto save_rest = [&](CheckpointOut& w) {
    w.integer(tracks ? 1 : 0);
    if (tracks) tracks->save(w);
  };
  if (!control.resuming()) {
    row();
    if (dump) write_lammps_dump(*dump, sys.step(), sys.snapshot(), sys.box());
  }
  const std::int64_t first = sys.step();
  Progress progress("md rod", last, quiet, first);
  progress.show_rate(n, "atom-steps");
  const auto t0 = std::chrono::steady_clock::now();
  while (sys.step() < last && stopped.empty()) {
    const std::int64_t step = sys.step();
    if (step == eq && !tracks) release();
    std::int64_t chunk = to_next(step, c.thermo);
    if (step < eq) {
      chunk = std::min(chunk, eq - step);
      if (c.rod_rescale_every > 0) chunk = std::min(chunk, to_next(step, c.rod_rescale_every));
    } else {
      chunk = std::min({chunk, to_next(step - eq, c.tracks.every), last - step});
    }
    sys.advance(static_cast<int>(chunk), c.dt);  // chunk <= thermo < 2^31 (config)
    const std::int64_t now = sys.step();
    if (now <= eq && c.rod_rescale_every > 0 && now % c.rod_rescale_every == 0)
      sys.rescale_temperature(c.temperature, nf);
    if (tracks && (now - eq) % c.tracks.every == 0) tracks->record(frame());
    if (now % c.thermo == 0 || now == last) row();
    if (dump && now % c.dump_every == 0) write_dump_frame(*dump, sys, c.dump_fields, sys.options().threads);
    progress.update(now);
    if (stopped.empty() && now < last && stop_md_with(control, sys, save_rest)) break;
  }
  progress.finish(sys.step());
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.atoms = static_cast<long>(n);
  r.steps = static_cast<long>(sys.step());
  r.steps_now = static_cast<long>(sys.step() - first);
  r.atom_steps_per_second = secs > 0 ? n * static_cast<double>(sys.step() - first) / secs : 0.0;
  r.step = sys.step(), r.last_step = last;
  r.potential_energy_per_atom = sys.potential_energy() / n;
  r.stress_gpa = sys.stress_gpa();
  rec.insert("md_atom_steps_per_second", r.atom_steps_per_second);
  rec.insert("run_seconds", secs);
  rec.insert("rod", toml::table{{"lattice_constant_A", c.rod_config.lattice_constant},
                                {"target_cells", toml::array{c.rod_config.target_cells[0], c.rod_config.target_cells[1],
                                                             c.rod_config.target_cells[2]}},
                                {"flyer_cells", c.rod_config.flyer_cells},
                                {"tile_A", tile_lengths(c.rod_config.lattice, c.rod_config.lattice_constant)},
                                {"flyer_atoms", nf},
                                {"target_atoms", static_cast<std::int64_t>(n) - nf},
                                {"impact_face_x_A", geo.impact_face},
                                {"target_length_A", geo.length},
                                {"cross_section_A", toml::array{geo.ly, geo.lz}},
                                {"flyer_velocity_A_per_ps", c.rod_velocity},
                                {"flyer_final_vx_A_per_ps", flyer_vx(sys, nf)},
                                {"equilibrate_steps", eq},
                                {"rescale_every", c.rod_rescale_every}});
  rec.insert("still", c.still);
  if (tracks) {
    tracks->write(out_dir);
    toml::table an;
    tracks->summarize(an);
    rec.insert("analysis", an);
  }
  return stopped;
}

}  // namespace mpmx::app::md
