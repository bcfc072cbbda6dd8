#include "mpmx/app/md/config.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <variant>

#include <fmt/format.h>

#include "mpmx/app/case_table.hpp"
#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/core/checked_count.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/md/physical_bounds.hpp"
#include "mpmx/particles/lattice_keys.hpp"
#include "mpmx/particles/tile_planes.hpp"

namespace mpmx::app::md {

namespace {

constexpr std::int64_t kMax64 = std::numeric_limits<std::int64_t>::max();

// A lattice constant whose atoms start no closer than a bond (md/physical_bounds.hpp).
void check_constant(io::Section& s, std::string_view key, double a, const particles::LatticeSpec& spec) {
  const std::string why =
      spec.plain_fcc() ? mpmx::md::fcc_constant_problem(a)
                       : mpmx::md::lattice_constant_problem(a, particles::nearest_neighbour_ratio(spec),
                                                            particles::lattice_name(spec.style));
  if (!why.empty()) s.check(false, key, why);
}

// What a [jet]'s or [rod]'s counts count: fcc's cubic cells, or the oriented lattice's tiles.
std::string sample_unit(const particles::LatticeSpec& spec) {
  if (spec.plain_fcc()) return "cells";
  const particles::TilePlanes t = particles::tile_planes(spec);
  return fmt::format("tiles of {:.6g} x {:.6g} x {:.6g} A", t.length[0], t.length[1], t.length[2]);
}

// Whether the [lattice] read makes a tile (else its keys were refused already).
bool tiles_known(const particles::LatticeSpec& spec) {
  return spec.constant > 0 && particles::orient_problem(spec).empty() &&
         (spec.style != particles::LatticeStyle::hcp || spec.c_over_a > 0);
}

// The target's planes along x, as a track's error states them.
std::string plane_spacing(const particles::TilePlanes& t) {
  if (t.x_planes.size() == 2 && t.x_planes[1] == 0.5) return fmt::format("every {} A", 0.5 * t.length[0]);
  std::string f;
  for (double x : t.x_planes) f += fmt::format("{}{:.6g}", f.empty() ? "" : ", ", x * t.length[0]);
  return fmt::format("at {} A in each tile of {:.6g} A", f, t.length[0]);
}

// [lattice]: the crystal (fcc, bcc or hcp in any orientation) and its initial strain.
// `sample`: the deck builds a [jet] or [rod], whose samples hold one element.
void read_lattice(io::Section& lat, bool sample, MdConfig& c) {
  particles::LatticeSpec& spec = c.lattice;
  particles::read_crystal_keys(lat, "type", spec);
  c.lattice_constant = lat.number("constant");
  lat.positive("constant", c.lattice_constant);
  spec.constant = c.lattice_constant;
  if (sample)
    lat.check(spec.style != particles::LatticeStyle::b2, "type",
              "a [jet] or [rod] sample is of one element (fcc, bcc or hcp); b2 applies to the periodic box and the "
              "[bar]");
  if (spec.style == particles::LatticeStyle::b2) {
    const auto* eam = std::get_if<EamSpec>(&c.potential);
    lat.check(eam && eam->elements.size() >= 2, "type",
              "b2 puts potential.elements[0] on the cube corners and elements[1] on the body centres: it needs an "
              "eam potential with two elements");
  }
  check_constant(lat, "constant", c.lattice_constant, spec);
  const auto cells = lat.integers("cells", 1, 1000);  // unit cells along x, y, z
  if (cells.size() == 3 || cells.size() == 1) {
    for (int d = 0; d < 3; ++d) c.cells[d] = static_cast<int>(cells[cells.size() == 3 ? d : 0]);
  } else {
    lat.check(false, "cells", "expected [nx, ny, nz] or [n]");
  }
  c.strain_x = lat.number("strain_x", 0.0);
  lat.check(c.strain_x > -0.5 && c.strain_x < 0.5, "strain_x", "must lie in (-0.5, 0.5)");
}

// [thermal]: the start temperature, its random stream, the relaxation.
void read_thermal(io::Section& th, MdConfig& c) {
  c.temperature = th.number("temperature", 0.0);
  th.temperature("temperature", c.temperature);
  c.seed = static_cast<std::uint64_t>(th.integer("seed", 1, 0, kMax64));
  c.relax_steps = th.integer("relax_steps", 0, 0, kMax64);
}

// Why a sample deck's run is NVE, as its refusals of an ensemble say.
std::string sample_is_nve(std::string_view sample) {
  const char* why = sample == "bar"   ? "its walls and the vacuum beyond them hold no pressure"
                    : sample == "jet" ? "its piston and free surfaces"
                                      : "open on every side; rod.rescale_every holds its temperature while it "
                                        "equilibrates";
  return fmt::format("a [{}] run is NVE ({}); ensembles apply to periodic boxes", sample, why);
}

// A thermostat's or barostat's period, `steps` steps of run.dt unless given; a given one
// must span 10 steps (LAMMPS advises 100 and 1000): the chains' Trotter steps resolve no
// shorter motion, and a run with one goes non-finite within a few steps.
double read_period(io::Section& run, std::string_view key, double steps, double dt) {
  const double period = run.number(key, steps * dt);
  if (!run.has(key)) return period;  // the default follows run.dt, whose errors were said
  run.positive(key, period);
  if (dt > 0)
    run.check(period >= 10 * dt, key,
              fmt::format("is {:.3g} steps of run.dt = {} ps: a Nose-Hoover period spans at least 10 (LAMMPS advises "
                          "{:g})",
                          period / dt, dt, steps));
  return period;
}

// [run] ensemble: nve, or the Nose-Hoover chain thermostat (nvt), with the MTK barostat
// (npt), or the barostat alone (nph), LAMMPS's fix nvt / npt / nph (md/nose_hoover.hpp);
// its target temperature is thermal.temperature, its periods t_damp_ps and p_damp_ps
// (LAMMPS's Tdamp and Pdamp: 100 and 1000 steps by default, as its manual advises);
// or nphug, the Hugoniostat (fix nphug): the shock axis's pressure_gpa, its thermostat's
// target from the Hugoniot's energy condition about the box the run starts with.
// `sample`: "bar", "jet" or "rod" for a deck of one (an NVE run), else "".
// Every key is refused where it has no effect, and only once: a refused ensemble leaves
// its keys unread rather than refused again one by one.
void read_ensemble(io::Section& run, std::string_view sample, MdConfig& c) {
  static constexpr const char* kKeys[] = {"t_damp_ps", "p_damp_ps", "barostat", "pressure_gpa", "shock_axis"};
  c.ensemble = run.choice("ensemble", {"nve", "nvt", "npt", "nph", "nphug"}, "nve");
  const bool refused = run.failed("ensemble") || (!sample.empty() && c.ensemble != "nve");
  if (!run.failed("ensemble")) run.check(sample.empty() || c.ensemble == "nve", "ensemble", sample_is_nve(sample));
  if (refused) {
    c.ensemble = "nve";
    for (const char* key : kKeys) run.ignore(key);
    return;
  }
  const bool hug = c.ensemble == "nphug";
  const bool tstat = c.ensemble == "nvt" || c.ensemble == "npt" || hug;
  const bool pstat = c.ensemble == "npt" || c.ensemble == "nph" || hug;
  NoseHooverOptions& nh = c.nose_hoover;
  nh.thermostat = tstat, nh.barostat = pstat, nh.temperature = c.temperature, nh.hugoniot = hug;
  // The Nose-Hoover chains' masses are kT over their frequencies: no kT, no motion.
  const char* kt_is = tstat ? "it is the thermostat's target"
                            : "the barostat's kT is the box's temperature at the start (its atoms at twice "
                              "thermal.temperature)";
  run.check(!(tstat || pstat) || c.temperature > 0, "ensemble",
            fmt::format("needs thermal.temperature > 0, not {} K: {}", c.temperature, kt_is));
  for (const char* key : kKeys) {
    const std::string_view k = key;
    const bool wanted = k == "t_damp_ps" ? tstat : k == "barostat" ? pstat && !hug : k == "shock_axis" ? hug : pstat;
    if (wanted || !run.has(key)) continue;
    run.check(false, key,
              sample.empty() ? fmt::format("has no use with ensemble = \"{}\"", c.ensemble)
                             : fmt::format("has no use: {}", sample_is_nve(sample)));
  }
  if (tstat) nh.t_damp = read_period(run, "t_damp_ps", 100, c.dt);
  if (!pstat) return;
  nh.p_damp = read_period(run, "p_damp_ps", 1000, c.dt);
  if (hug) {  // uniaxial: the shock axis dilates to its target pressure, the others stay
    const std::string axis = run.choice("shock_axis", {"x", "y", "z"}, "x");
    nh.isotropic = false;
    nh.axes = {axis == "x", axis == "y", axis == "z"};
    const double p = run.number("pressure_gpa");
    nh.pressure = {p, p, p};
    run.check(p >= 0, "pressure_gpa", "a shock's pressure is compressive (>= 0)");
    return;
  }
  nh.isotropic = run.choice("barostat", {"iso", "aniso"}, "iso") == "iso";
  if (nh.isotropic) {  // one target, the mean pressure's
    const double p = run.number("pressure_gpa", 0.0);
    nh.pressure = {p, p, p};
  } else {  // a target for each axis's normal pressure
    const auto p = run.numbers("pressure_gpa", {0.0, 0.0, 0.0});
    if (p.size() == 3) std::copy(p.begin(), p.end(), nh.pressure.begin());
    else run.check(false, "pressure_gpa", "with barostat = \"aniso\": [px, py, pz]");
  }
}

// [run]: the time step and length, output, neighbour skin, precision, deformation.
// `sample`: "bar", "jet" or "rod" for a deck of one ("": a periodic box); a [jet] sets
// the length itself.
void read_run(io::Section& run, std::string_view sample, MdConfig& c) {
  const bool jet = sample == "jet";
  c.dt = run.number("dt");
  run.positive("dt", c.dt);
  run.check(c.dt <= 0.01, "dt", "is above 0.01 ps; metal MD needs about 0.001 ps");
  if (!jet) c.steps = run.integer("steps", 0, kMax64);  // a jet's follow from its duration
  c.thermo = run.integer("thermo", 100, 1, INT_MAX);
  read_ensemble(run, sample, c);
  c.dump_every = run.integer("dump_every", 0, 0, INT_MAX);
  run.check(c.dump_every == 0 || c.dump_every % c.thermo == 0 || jet, "dump_every",
            "must be 0 (no dump) or a multiple of thermo");
  c.dump_fields = run.strings("dump_fields", {});
  const std::string fields_problem = dump_fields_problem(c.dump_fields);
  run.check(fields_problem.empty(), "dump_fields", fields_problem);
  run.check(c.dump_fields.empty() || c.dump_every > 0, "dump_fields", "needs dump_every > 0 (there is no dump)");
  if (dump_needs_per_atom(c.dump_fields)) c.options.per_atom = true;
  c.options.skin = run.number("skin", 1.0);
  run.non_negative("skin", c.options.skin);
  c.options.mixed_precision = run.choice("precision", {"double", "mixed"}, "double") == "mixed";
  c.options.deformation =
      run.choice("deformation", {"boundary", "affine"}, "boundary") == "affine" ? Deformation::affine
                                                                                : Deformation::boundary;
  const bool has_rate = run.has("strain_rate_per_s");
  const bool has_grad = run.has("velocity_gradient_per_ps");
  run.check(!(has_rate && has_grad), "strain_rate_per_s",
            "give either strain_rate_per_s or velocity_gradient_per_ps, not both");
  if (has_rate) c.velocity_gradient[0] = run.number("strain_rate_per_s") * 1e-12;
  if (has_grad) {
    const auto g = run.numbers("velocity_gradient_per_ps");
    if (g.size() == 9) std::copy(g.begin(), g.end(), c.velocity_gradient.begin());
    else run.check(false, "velocity_gradient_per_ps", "expected 9 numbers (row-major dv_i/dx_j)");
  }
  c.streaming = run.boolean("streaming_start", false);
  run.check(c.ensemble == "nve" || (!has_rate && !has_grad && !c.streaming), "ensemble",
            "a thermostat or barostat runs an undeformed box: no strain_rate_per_s, velocity_gradient_per_ps or "
            "streaming_start");
}

// [scan]: the lattice-constant scan (M1).
void read_scan(io::Section& scan, MdConfig& c) {
  c.scan_from = scan.number("lattice_from");
  scan.positive("lattice_from", c.scan_from);
  check_constant(scan, "lattice_from", c.scan_from, c.lattice);
  c.scan_to = scan.number("lattice_to");
  scan.check(c.scan_to > c.scan_from, "lattice_to", "must exceed lattice_from");
  c.scan_points = scan.integer_int("points", 41, 3, 100000);
}

// [elastic]: the 0 K tensor of the deck's crystal.
void read_elastic(io::Section& e, MdConfig& c) {
  c.elastic = true;
  c.elastic_temperature = e.number("temperature", 0.0);
  e.temperature("temperature", c.elastic_temperature);
  const bool hot = c.elastic_temperature > 0;
  // A hot crystal's tensor is that of its thermal lattice constant, which the deck gives
  // (an NPT run's averages); the 0 K minimum would hold it under the thermal pressure.
  c.elastic_at_minimum = e.choice("at", {"minimum", "deck"}, hot ? "deck" : "minimum") == "minimum";
  e.check(!hot || !c.elastic_at_minimum, "at",
          "\"minimum\" is the 0 K crystal's constant; at a temperature give the thermal one as [lattice].constant "
          "(an npt run's averages.lattice_constant_x_A) and at = \"deck\"");
  c.elastic_strain = e.number("strain", hot ? 0.01 : c.elastic_strain);
  e.check(c.elastic_strain >= 1e-7 && c.elastic_strain <= 0.05, "strain",
          "must lie in [1e-7, 0.05]: larger strains measure the nonlinear response, smaller ones round-off");
  c.elastic_relax = e.boolean("relax", c.elastic_relax);
  e.check(!hot || !e.has("relax"), "relax", "applies at 0 K only: a hot box's atoms find their places themselves");
  c.elastic_equilibrate_steps = e.integer_int("equilibrate_steps", c.elastic_equilibrate_steps, 2, 100000000);
  c.elastic_sample_steps = e.integer_int("sample_steps", c.elastic_sample_steps, 200, 100000000);
  e.check(hot || !e.has("equilibrate_steps"), "equilibrate_steps", "applies with a temperature only");
  e.check(hot || !e.has("sample_steps"), "sample_steps", "applies with a temperature only");
  e.check(c.lattice.style != particles::LatticeStyle::b2, "at",
          "a b2 box's tensor is not computed (two elements); fcc, bcc and hcp are");
}

// [bar]: the direct-MD bar between walls.
void read_bar(io::Section& bar, MdConfig& c) {
  c.bar = true;
  BarConfig& b = c.bar_config;
  b.cells_x = bar.integer_int("cells_x", 2, 100000);
  b.cells_yz = bar.integer_int("cells_yz", 1, 1000);
  b.strain_left = bar.number("strain_left", 0.0);
  bar.check(b.strain_left > -0.5 && b.strain_left < 0.5, "strain_left", "must lie in (-0.5, 0.5)");
  b.split = bar.number("split", 0.5);
  bar.check(b.split > 0 && b.split < 1, "split", "must lie in (0, 1)");
  b.piston_velocity = bar.number("piston_velocity", 0.0);
  b.bins = bar.integer_int("bins", 100, 1, 100000);
  c.bar_every = bar.integer("output_every", 100, 1, INT_MAX);
  b.lattice_constant = c.lattice_constant;
  b.lattice = c.lattice;
  b.temperature = c.temperature;
  b.seed = c.seed;
}

// [jet] (sec. 7.1): the sample (scale, cells, piston, notch, velocity); `run` is the
// deck's [run] table, which a jet deck leaves the length and thermo rows to [jet].
void read_jet_sample(io::Section& jet, io::Section& run, bool has_bar, MdConfig& c) {
  run.check(!run.has("steps"), "steps",
            "a [jet] deck sets its length by jet.duration_ps (times jet.scale); drop run.steps");
  run.check(!run.has("thermo"), "thermo", "a [jet] deck records every jet.record_every_ps; drop run.thermo");
  if (has_bar) jet.error("a deck holds [bar] or [jet], not both");
  c.jet = true;
  JetConfig& j = c.jet_config;
  j.scale = jet.number("scale", 1.0);
  jet.check(j.scale > 0 && j.scale <= 10, "scale", "must lie in (0, 10]");
  const auto cells = jet.integers("cells", 1, 100000);  // at scale 1: x (piston included), y, z
  if (cells.size() == 3) {
    for (int d = 0; d < 3; ++d) j.cells[d] = static_cast<int>(cells[d]);
  } else {
    jet.check(false, "cells",
              "expected [nx, ny, nz] (fcc cells, or an oriented [lattice]'s tiles, at scale 1; z is not scaled)");
  }
  j.piston_cells = jet.integer_int("piston_cells", 1, 100000);
  j.notch_depth_nm = jet.number("notch_depth_nm");
  jet.non_negative("notch_depth_nm", j.notch_depth_nm);
  j.velocity_km_s = jet.number("velocity_km_s", 2.5);
  jet.check(j.velocity_km_s > 0 && j.velocity_km_s <= 20, "velocity_km_s", "must lie in (0, 20] km/s");
  j.lattice_constant = c.lattice_constant;
  j.lattice = c.lattice;
  j.temperature = c.temperature;
  j.seed = c.seed;
  if (cells.size() == 3 && j.scale > 0 && j.scale <= 10 && tiles_known(c.lattice)) {
    const std::string tiles = sample_unit(c.lattice);
    const double tx = particles::tile_planes(c.lattice).length[0];
    jet.check(j.nx() >= 2 && j.ny() >= 1, "cells",
              fmt::format("at scale {} the sample is {} x {} {}: needs at least 2 x 1", j.scale, j.nx(), j.ny(),
                          tiles));
    jet.check(j.npiston() >= 1 && j.npiston() < j.nx(), "piston_cells",
              fmt::format("at scale {} the piston is {} of {} {}: needs at least 1 and fewer than the sample",
                          j.scale, j.npiston(), j.nx(), tiles));
    jet.check(j.notch_depth_A() < (j.nx() - j.npiston()) * tx, "notch_depth_nm",
              fmt::format("at scale {} the notch ({} A) is not shallower than the block ({} A: {} {})", j.scale,
                          j.notch_depth_A(), (j.nx() - j.npiston()) * tx, j.nx() - j.npiston(), tiles));
  }
}

// [jet]'s records: the bins and the run's length and record interval, in steps of run.dt.
void read_jet_records(io::Section& jet, io::Section& run, MdConfig& c) {
  const JetConfig& j = c.jet_config;
  const auto bins = jet.integers("bins", 1, 100000);
  if (bins.size() == 2) {
    c.jet_bins = {static_cast<int>(bins[0]), static_cast<int>(bins[1])};
    jet.check(bins[0] * bins[1] <= 10'000'000, "bins",
              "more than 10^7 bins: each record's tables would not fit (400 x 50 is the seed's)");
  } else {
    jet.check(false, "bins", "expected [nx, ny] (bins over the sample's x and y)");
  }
  const double duration = jet.number("duration_ps");
  jet.positive("duration_ps", duration);
  const double every = jet.number("record_every_ps");
  jet.positive("record_every_ps", every);
  if (duration > 0 && every > 0 && c.dt > 0 && j.scale > 0) {
    const double steps = j.scale * duration / c.dt, per = j.scale * every / c.dt;
    jet.check(steps < 1e15, "duration_ps", fmt::format("times the scale is {:.3g} steps: too many", steps));
    jet.check(per >= 1 && per < INT_MAX, "record_every_ps",
              fmt::format("times the scale is {:.6g} steps of run.dt: needs 1 to 2^31 - 1 (rounded)", per));
    if (steps < 1e15 && per >= 1 && per < INT_MAX) {
      c.steps = std::llround(steps);
      c.jet_every = std::llround(per);
      // Whole steps only (to rounding of the product): 100.5 steps is not silently 100.
      jet.check(std::abs(steps - static_cast<double>(c.steps)) <= 1e-6 * std::max(1.0, steps), "duration_ps",
                fmt::format("times jet.scale is {:.9g} steps of run.dt = {} ps: not a whole number", steps, c.dt));
      jet.check(std::abs(per - static_cast<double>(c.jet_every)) <= 1e-6 * std::max(1.0, per), "record_every_ps",
                fmt::format("times jet.scale is {:.9g} steps of run.dt = {} ps: not a whole number", per, c.dt));
      jet.check(c.steps % c.jet_every == 0, "record_every_ps",
                fmt::format("{} steps per record does not divide the run's {} steps", c.jet_every, c.steps));
      c.thermo = c.jet_every;
      run.check(c.dump_every % c.jet_every == 0, "dump_every",
                fmt::format("must be 0 (no dump) or a multiple of the {} steps per record", c.jet_every));
    }
  }
}

// The rod's tracks: each region must hold an atomic plane of the target at the start.
void check_track_planes(io::Section& an, const MdConfig& c) {
  if (!tiles_known(c.lattice)) return;  // the [lattice] said why
  const RodConfig& r = c.rod_config;
  // The target's atomic planes lie at face + (i + f) L, i = 0 .. nx - 1, f the tile's
  // plane fractions (md/rod.hpp's frame; fcc along the axes: every a/2): a region between
  // two planes would hold no atom at the start.
  const particles::TilePlanes tp = particles::tile_planes(c.lattice);
  const double L = tp.length[0], face = r.flyer_cells * L;
  const double last = face + (r.target_cells[0] - 1 + tp.x_planes.back()) * L;
  for (const TrackSpec& t : c.tracks.tracks) {
    bool holds = false;
    const double first_tile = std::max(0.0, std::floor((t.lo - face) / L) - 1);
    for (double i = first_tile; i < r.target_cells[0] && !holds && face + i * L < t.hi; ++i)
      for (double f : tp.x_planes) {
        const double x = face + (i + f) * L;
        holds = holds || (x >= t.lo - 1e-9 * L && x < t.hi);
      }
    if (!holds)
      an.error(fmt::format("track \"{}\": x = [{}, {}) A holds no atomic plane of the target (planes {} from the "
                           "impact face at {} A to {} A)",
                           t.name, t.lo, t.hi, plane_spacing(tp), face, last));
  }
}

// [rod] (seed 004 sec. 4.1.1): the flyer and target, the equilibration, the flyer's speed;
// with the region tracks of [[track]], [analysis] and [profile] (app/region_tracks.hpp).
void read_rod(io::Section& root, io::Section& rod, bool other, MdConfig& c) {
  if (other) rod.error("a deck holds one of [bar], [jet] and [rod]");
  c.rod = true;
  RodConfig& r = c.rod_config;
  const auto cells = rod.integers("target_cells", 1, 100000);
  if (cells.size() == 3) {
    for (int d = 0; d < 3; ++d) r.target_cells[d] = static_cast<int>(cells[d]);
  } else {
    rod.check(false, "target_cells",
              "expected [nx, ny, nz] (fcc cells of lattice.constant, or an oriented [lattice]'s tiles)");
  }
  r.flyer_cells = rod.integer_int("flyer_cells", 1, 100000);
  r.lattice_constant = c.lattice_constant;
  r.lattice = c.lattice;
  r.temperature = c.temperature;
  r.seed = c.seed;
  c.rod_velocity = rod.number("flyer_velocity");
  rod.check(c.rod_velocity > 0 && c.rod_velocity <= 200, "flyer_velocity",
            "must lie in (0, 200] Angstrom/ps (along +x, into the target)");
  c.rod_equilibrate_steps = rod.integer("equilibrate_steps", 0, 0, kMax64);
  c.rod_rescale_every = rod.integer("rescale_every", 50, 0, INT_MAX);
  rod.check(c.rod_rescale_every == 0 || c.temperature > 0, "rescale_every",
            "rescales to thermal.temperature, which is 0: set rescale_every = 0 or a temperature");
  auto an = root.optional_table("analysis");
  read_track_settings(root, an, c.thermo, c.tracks);
  check_track_planes(an, c);
  rod.check(c.rod_rescale_every == 0 || c.rod_equilibrate_steps % c.rod_rescale_every == 0, "equilibrate_steps",
            "must be a multiple of rescale_every (the rescaling ends with the equilibration)");
}

}  // namespace

MdConfig read_md_config(io::Deck& deck) {
  MdConfig c;
  c.deck_file = deck.name();
  const std::string deck_dir = std::filesystem::path(deck.name()).parent_path().string();
  auto root = deck.root();
  const CaseTable cs = read_case_table(root, deck.name(), false, "metal");
  c.id = cs.id;
  c.title = cs.title;
  c.seed_ref = cs.seed;

  c.potential = read_potential(root.table("potential"), deck_dir);

  auto lat = root.table("lattice");
  read_lattice(lat, root.has("jet") || root.has("rod"), c);
  auto th = root.optional_table("thermal");
  read_thermal(th, c);
  auto run = root.table("run");
  // The sample a deck builds (several: refused below, by the sample's table).
  const std::string_view sample = root.has("jet") ? "jet" : root.has("rod") ? "rod" : root.has("bar") ? "bar" : "";
  read_run(run, sample, c);
  auto scan = root.optional_table("scan");
  if (scan.present()) read_scan(scan, c);
  auto elastic = root.optional_table("elastic");
  if (elastic.present()) {
    read_elastic(elastic, c);
    if (root.has("bar") || root.has("jet") || root.has("rod"))
      elastic.error("is the periodic box's: a deck with [bar], [jet] or [rod] has none (give [elastic] its own deck)");
  }
  auto bar = root.optional_table("bar");
  if (bar.present()) read_bar(bar, c);
  auto jet = root.optional_table("jet");
  if (jet.present()) {
    read_jet_sample(jet, run, bar.present(), c);
    read_jet_records(jet, run, c);
  }
  auto rod = root.optional_table("rod");
  if (rod.present()) read_rod(root, rod, bar.present() || jet.present(), c);
  // A sample ([bar], [jet], [rod]) runs its own set-up: the periodic box's keys would be
  // read and do nothing there, so each is refused with why.
  if (bar.present() || jet.present() || rod.present()) {
    const std::string sample = bar.present() ? "[bar]" : jet.present() ? "[jet]" : "[rod]";
    const std::string box_only = fmt::format("has no use in a {} run: it applies to the periodic box", sample);
    for (const char* key : {"strain_rate_per_s", "velocity_gradient_per_ps", "streaming_start", "deformation"})
      run.check(!run.has(key), key, box_only + " (a sample is not deformed as a whole)");
    th.check(!th.has("relax_steps"), "relax_steps",
             box_only + (rod.present() ? " (a rod's target equilibrates by rod.equilibrate_steps)" : ""));
    lat.check(!lat.has("strain_x"), "strain_x",
              box_only + (bar.present() ? " (a bar's strain is bar.strain_left)" : ""));
    if (bar.present())
      for (const char* key : {"dump_every", "dump_fields"})
        run.check(!run.has(key), key, "has no use in a [bar] run: it writes bar_stress.csv, no dump frames");
  }
  // The run counts its steps from the start, relaxation or equilibration included.
  th.check(checked_sum(c.relax_steps, c.steps).has_value(), "relax_steps",
           "plus run.steps is more steps than a run can count (2^63 - 1)");
  rod.check(checked_sum(c.rod_equilibrate_steps, c.steps).has_value(), "equilibrate_steps",
            "plus run.steps is more steps than a run can count (2^63 - 1)");
  deck.finish();
  return c;
}

}  // namespace mpmx::app::md
