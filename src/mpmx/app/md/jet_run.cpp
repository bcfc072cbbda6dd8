#include "mpmx/app/md/jet_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/app/md/run.hpp"
#include "mpmx/app/reported_quantities.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/progress.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/io/atomic_file.hpp"
#include "mpmx/io/vtk.hpp"

namespace mpmx::app::md {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kGPa = units::eV_per_A3_in_GPa;

void write_bins_csv(const std::string& path, const BinFields& f) {
  // Whole or not at all, and a refused write is the machine's failure (SystemError), never
  // a stop by the physics that would publish a cut table.
  std::ostringstream csv;
  csv << "ix,iy,x_A,y_A,atoms,density_g_cm3,temperature_K,vx_km_s,vy_km_s,sxx_GPa,syy_GPa,szz_GPa,sxy_GPa,"
         "sxz_GPa,syz_GPa\n";
  const BinGrid& g = f.grid;
  for (int iy = 0; iy < g.ny; ++iy)
    for (int ix = 0; ix < g.nx; ++ix) {
      const int k = ix + g.nx * iy;
      const Mat3& s = f.stress[k];
      csv << fmt::format("{},{},{:.6g},{:.6g},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g},{:.8g}\n",
                         ix, iy, g.x_centre(ix), g.y_centre(iy), f.atoms[k], f.density_g_cm3(k), f.temperature[k],
                         0.1 * f.vx[k], 0.1 * f.vy[k], s[0] * kGPa, s[4] * kGPa, s[8] * kGPa, s[1] * kGPa,
                         s[2] * kGPa, s[5] * kGPa);
    }
  io::write_file_atomic(path, csv.str());
}

// ParaView image: one point per bin centre (stress GPa, density g/cm^3, T K, v km/s),
// positions in nm: the jet's continuum decks are nm_ps_GPa, and both sit side by side in
// ParaView (the CSV keeps Angstrom, as its x_A, y_A say).
constexpr double kNmPerA = 0.1;

void write_bins_vti(const std::string& path, const BinFields& f) {
  const BinGrid& g = f.grid;
  io::vtk::Field sxx{"sxx_GPa", 1, {}}, stress{"stress_GPa", 9, {}}, rho{"density_g_cm3", 1, {}},
      temp{"temperature_K", 1, {}}, vel{"velocity_km_s", 3, {}}, n{"atoms", 1, {}};
  for (std::size_t k = 0; k < f.atoms.size(); ++k) {
    sxx.values.push_back(f.stress[k][0] * kGPa);
    for (double v : f.stress[k]) stress.values.push_back(v * kGPa);
    rho.values.push_back(f.density_g_cm3(static_cast<int>(k)));
    temp.values.push_back(f.temperature[k]);
    for (double v : {f.vx[k], f.vy[k], f.vz[k]}) vel.values.push_back(0.1 * v);
    n.values.push_back(f.atoms[k]);
  }
  io::vtk::write_image(path, {g.nx, g.ny, 1},
                       {kNmPerA * g.x_centre(0), kNmPerA * g.y_centre(0), kNmPerA * 0.5 * g.lz},
                       {kNmPerA * g.dx, kNmPerA * g.dy, kNmPerA * g.lz}, {sxx, stress, rho, temp, vel, n});
}

}  // namespace

BinGrid jet_grid(const JetGeometry& geo, int nx, int ny) {
  BinGrid g;
  g.nx = nx, g.ny = ny;
  g.x0 = geo.x0;
  g.dx = geo.length / nx;
  g.dy = geo.ly / ny;
  g.lz = geo.lz;
  return g;
}

double shock_front(const BinFields& col, double piston_face, double up) {
  const BinGrid& g = col.grid;
  int prev = -1;  // the last column behind the front (shocked, at rest)
  for (int ix = 0; ix < g.nx; ++ix) {
    if (g.x_centre(ix) < piston_face || col.atoms[ix] == 0) continue;
    if (col.vx[ix] < -0.5 * up) {
      if (prev < 0) return kNaN;  // the first block column is unshocked: no front yet
      const double v0 = col.vx[prev], v1 = col.vx[ix], x0 = g.x_centre(prev), x1 = g.x_centre(ix);
      return x0 + (x1 - x0) * (v0 + 0.5 * up) / (v0 - v1);
    }
    prev = ix;
  }
  return kNaN;
}

double shock_speed(const std::vector<double>& t, const std::vector<double>& front, double piston_face,
                   double tip0, double up, double width) {
  double n = 0, st = 0, sx = 0, stt = 0, stx = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double x = front[k];
    if (!(x > piston_face + width && x < tip0 - up * t[k] - width)) continue;
    n += 1, st += t[k], sx += x, stt += t[k] * t[k], stx += t[k] * x;
  }
  if (n < 3) return kNaN;
  return (n * stx - st * sx) / (n * stt - st * st);
}

namespace {

// What a jet run tracks record by record: the time, the shock front and the most
// compressive column, and that column's most compressive value over the run.
struct JetTrack {
  std::vector<double> times, front_x, compressions;
  double peak = 0;  // GPa
};

// The figures run.json takes: the lab-frame shock speed against the Hugoniot's, the
// peak and plateau compression.
void insert_jet_figures(const MdConfig& c, const JetGeometry& geo, const BinGrid& grid, const JetTrack& track,
                        toml::table& rec) {
  const double up = 10.0 * c.jet_config.velocity_km_s;  // km/s -> A/ps
  const double us = shock_speed(track.times, track.front_x, geo.piston_face, geo.notch_tip, up, grid.dx);
  const double hugoniot = 3.94 + 1.49 * c.jet_config.velocity_km_s - c.jet_config.velocity_km_s;  // km/s, lab
  rec.insert("shock_speed_km_s", 0.1 * us);  // NaN (JSON null) when the front was never seen
  rec.insert("hugoniot_lab_shock_speed_km_s", hugoniot);
  rec.insert("peak_stress_gpa", track.peak);
  // The plateau: the median of each record's most compressive column while the front
  // runs through the full-width block (the records the shock speed is fitted to), less
  // sensitive to one noisy column than the peak.
  std::vector<double> plateau;
  for (std::size_t k = 0; k < track.times.size(); ++k)
    if (track.front_x[k] > geo.piston_face + grid.dx &&
        track.front_x[k] < geo.notch_tip - up * track.times[k] - grid.dx)
      plateau.push_back(track.compressions[k]);
  std::sort(plateau.begin(), plateau.end());
  rec.insert("plateau_stress_gpa", plateau.empty() ? kNaN : plateau[plateau.size() / 2]);
}

// run.json's "jet": the sample, its bins and records, the files written.
toml::table jet_table(const MdConfig& c, const JetGeometry& geo, const BinGrid& grid, std::size_t records) {
  return toml::table{{"scale", c.jet_config.scale},
                     {"cells", toml::array{c.jet_config.nx(), c.jet_config.ny(), c.jet_config.nz()}},
                     {"tile_A", tile_lengths(geo.lattice, geo.lattice.constant)},
                     {"piston_cells", c.jet_config.npiston()},
                     {"piston_atoms", geo.piston_atoms},
                     {"notch_depth_A", c.jet_config.notch_depth_A()},
                     {"velocity_km_s", c.jet_config.velocity_km_s},
                     {"x0_A", geo.x0},
                     {"length_A", geo.length},
                     {"ly_A", geo.ly},
                     {"lz_A", geo.lz},
                     {"piston_face_A", geo.piston_face},
                     {"notch_tip_A", geo.notch_tip},
                     {"bins", toml::array{grid.nx, grid.ny}},
                     {"record_every_steps", c.jet_every},
                     {"records", static_cast<std::int64_t>(records)},
                     {"bins_series", "md_bins.pvd"},
                     {"bins_series_length_unit", "nm"},
                     {"profile_csv", "jet_profile.csv"},
                     {"front_csv", "jet_front.csv"}};
}

}  // namespace

std::string run_jet(const MdConfig& c, const Potential& pot, const std::string& out_dir, MdRunSummary& r,
                    toml::table& rec, RunControl& control, bool quiet) {
  JetGeometry geo;
  System sys = build_jet(c.jet_config, pot, c.options, &geo);
  JetTrack track;
  if (control.resuming()) {
    const Tracked t = resume_md(control, sys, c.steps);
    if (t.size() != 4 || t[0].size() != 1 || t[1].size() != t[2].size() || t[1].size() != t[3].size())
      throw InputError(fmt::format("{}/checkpoint.bin: its jet track is not one a jet run writes", out_dir));
    track.peak = t[0][0], track.times = t[1], track.front_x = t[2], track.compressions = t[3];
  }
  const BinGrid grid = jet_grid(geo, c.jet_bins[0], c.jet_bins[1]);
  BinGrid colgrid = grid;
  colgrid.ny = 1, colgrid.dy = geo.ly;
  const double up = 10.0 * c.jet_config.velocity_km_s;  // km/s -> A/ps
  fs::create_directories(fs::path(out_dir) / "bins");   // only once the sample is built
  fs::create_directories(fs::path(out_dir) / "vtk");
  io::vtk::Series series((fs::path(out_dir) / "md_bins.pvd").string());
  if (control.resuming()) series.restore_up_to(sys.time());
  RunTables& tables = control.tables();
  std::ofstream& profile = tables.open("jet_profile.csv", "step,time_ps,ix,x_A,atoms,density_g_cm3,vx_km_s,sxx_GPa\n");
  std::ofstream& fronts = tables.open("jet_front.csv", "step,time_ps,front_x_A,notch_tip_x_A,peak_compression_GPa\n");
  std::ofstream& thermo =
      tables.open("thermo.csv", "step,time_ps,pe_per_atom_eV,ke_per_atom_eV,etotal_per_atom_eV,temperature_K\n");
  std::ofstream* dump = c.dump_every > 0 ? &tables.open("dump.lammpstrj") : nullptr;

  const double n = static_cast<double>(sys.atoms().size());
  std::string stopped;
  auto record = [&] {
    const Atoms a = sys.snapshot();
    const BinFields f = bin_fields(a, sys.type_mass(), sys.per_atom_virial(), grid);
    const BinFields col = bin_fields(a, sys.type_mass(), sys.per_atom_virial(), colgrid);
    const std::string name = fmt::format("md_bins_{:06d}", sys.step());
    write_bins_csv((fs::path(out_dir) / "bins" / (name + ".csv")).string(), f);
    write_bins_vti((fs::path(out_dir) / "vtk" / (name + ".vti")).string(), f);
    series.add(sys.time(), "vtk/" + name + ".vti");
    double compression = 0;
    for (int ix = 0; ix < colgrid.nx; ++ix) {
      const double sxx = col.stress[ix][0] * kGPa;
      compression = std::max(compression, -sxx);
      profile << fmt::format("{},{:.6f},{},{:.6g},{},{:.6g},{:.6g},{:.8g}\n", sys.step(), sys.time(), ix,
                             colgrid.x_centre(ix), col.atoms[ix], col.density_g_cm3(ix), 0.1 * col.vx[ix], sxx);
    }
    track.peak = std::max(track.peak, compression);
    track.compressions.push_back(compression);
    const double xf = shock_front(col, geo.piston_face, up);
    track.times.push_back(sys.time());
    track.front_x.push_back(xf);
    fronts << fmt::format("{},{:.6f},{:.8g},{:.8g},{:.8g}\n", sys.step(), sys.time(), xf,
                          geo.notch_tip - up * sys.time(), compression);
    fronts.flush();  // a long run can be followed as it goes
    const double pe = sys.potential_energy() / n, ke = sys.kinetic_energy() / n;
    thermo << fmt::format("{},{:.6f},{:.12g},{:.12g},{:.12g},{:.6g}\n", sys.step(), sys.time(), pe, ke, pe + ke,
                          sys.temperature());
    stopped = first_non_finite(sys.step(), sys.time(), "ps",
                               {{"the potential energy (eV/atom)", pe},
                                {"the kinetic energy (eV/atom)", ke},
                                {"the temperature (K)", sys.temperature()}});
  };
  if (!control.resuming()) {
    record();
    if (dump) write_dump_frame(*dump, sys, c.dump_fields, sys.options().threads);
  }
  const std::int64_t first = sys.step();
  Progress progress("md jet", c.steps, quiet, first);
  progress.show_rate(n, "atom-steps");
  const auto t0 = std::chrono::steady_clock::now();
  std::int64_t done = first;
  while (done < c.steps && stopped.empty()) {
    const std::int64_t chunk = std::min<std::int64_t>(c.jet_every, c.steps - done);
    sys.advance(static_cast<int>(chunk), c.dt);  // jet_every < INT_MAX (config)
    done += chunk;
    record();
    if (dump && sys.step() % c.dump_every == 0) write_dump_frame(*dump, sys, c.dump_fields, sys.options().threads);
    progress.update(done);
    if (stopped.empty() && done < c.steps &&
        stop_md_at(control, sys, {{track.peak}, track.times, track.front_x, track.compressions}))
      break;
  }
  progress.finish(done);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.atoms = static_cast<long>(n);
  r.steps = static_cast<long>(sys.step());
  r.steps_now = static_cast<long>(sys.step() - first);
  r.atom_steps_per_second = secs > 0 ? n * static_cast<double>(sys.step() - first) / secs : 0.0;
  r.step = sys.step(), r.last_step = c.steps;
  r.potential_energy_per_atom = sys.potential_energy() / n;
  r.stress_gpa = sys.stress_gpa();
  insert_jet_figures(c, geo, grid, track, rec);
  rec.insert("md_atom_steps_per_second", r.atom_steps_per_second);
  rec.insert("run_seconds", secs);
  rec.insert("jet", jet_table(c, geo, grid, track.times.size()));
  return stopped;
}

}  // namespace mpmx::app::md
