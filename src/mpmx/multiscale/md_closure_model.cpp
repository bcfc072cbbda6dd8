#include "mpmx/multiscale/md_closure_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/budget.hpp"
#include "mpmx/md/declared_lattice.hpp"
#include "mpmx/md/elastic_constants.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/md/potential/registry.hpp"
#include "mpmx/particles/lattice_keys.hpp"

namespace mpmx::multiscale {

using material::Context;
using material::Material;
using material::Model;

namespace {
constexpr double kMaxAtomsPerPoint = 1e6;  // a box past this is no material point's

// The volume of a point's unstrained box at lattice constant a, A^3.
double box_volume(const MdClosureConfig& md, double a) {
  particles::LatticeSpec spec = md.lattice;
  spec.constant = a;
  const auto t = particles::lattice_tile(spec);
  return t.length[0] * t.length[1] * t.length[2] * md.cells * md.cells * md.cells;
}
}  // namespace

double MdClosureModel::wave_speed(int, double density, double) const { return std::sqrt(c11 / density); }

std::string MdClosureModel::time_step_problem(double dt) const {
  if (!(md.dt > 0) || md.md_steps(dt) > 0) return "";
  if (const double steps = dt * md.units.time_ps / md.dt; steps >= std::numeric_limits<int>::max())
    return fmt::format("is {:.4g} MD steps of material.md.dt = {} ps, more than the {} a macro step may take", steps,
                       md.dt, std::numeric_limits<int>::max());
  return fmt::format("is {} ps, not a whole number of MD steps of material.md.dt = {} ps", dt * md.units.time_ps,
                     md.dt);
}

material::Model::Shocked MdClosureModel::shocked(int dim, double up) const {
  Shocked r{1.0, wave_speed(dim, rho, 0.0), false};
  if (!md.stiffness || !(up != 0.0)) return r;
  for (int a = 0; a < dim; ++a) {
    const double J = md.stiffness->shock_compression(a, std::abs(up), rho, md.units.stress_GPa);
    if (!std::isfinite(J)) continue;
    // The points' density is the 0 K crystal's; J is against it.
    const double c = std::sqrt(std::max(md.stiffness->modulus_at(J) / md.units.stress_GPa, c11) * J / rho);
    if (!r.from_hugoniot || c > r.wave_speed) r = {J, c, true};
  }
  return r;
}

material::PointCost MdClosureModel::point_cost(double dt) const {
  material::PointCost c;
  const double n[3] = {double(md.cells), double(md.cells), double(md.cells)};
  constexpr double kClosureBytesPerPoint = 256;  // rotation, group, deviation, stress and shape records
  // Another crystal than fcc along the axes: as the fcc box of its atoms and density.
  const double atoms = md.atoms_per_point(), cells = std::cbrt(atoms / 4.0);
  const double a_fcc = md.lattice.plain_fcc() ? a0 : std::cbrt(4.0 / number_density);
  c.bytes = md::kept_box_bytes(md.lattice.plain_fcc() ? md.cells : cells, a_fcc, cutoff + md.skin) +
            kClosureBytesPerPoint;
  // A Cu-like fcc box (a = 3.615 A) reached by an 8 A cutoff plus skin, whole (md/budget's fit).
  c.scratch_bytes = md::box_bytes(n, 3.615, 8.0 + md.skin);
  c.atoms = md.atoms_per_point();
  c.steps_per_step = dt > 0 && md.dt > 0 ? std::max(1.0, dt / md.dt) : 1.0;
  c.setup_steps = static_cast<double>(md.relax_steps);
  if (md.prepare == BoxPrepare::npt && !md.prepared)  // the NPT box the run starts with: one box
    c.prepare_atom_steps = static_cast<double>(md.atoms_per_point()) * static_cast<double>(md.prepare_steps);
  c.size_key = "material.md.cells and grid.cells";
  c.atom_steps_per_second = measured_rate();
  return c;
}

// One box of the deck stepped on this core (md::measure_atom_steps_per_second): the rate
// `check` scales the work by, where a typed-in figure would be this build's and machine's
// only by luck.
double MdClosureModel::measured_rate() const {
  if (!md::complete(md.potential)) return 0.0;
  try {
    md::Potential pot(md.potential);
    md::SystemOptions o;
    o.skin = md.skin;
    o.mixed_precision = md.mixed_precision;
    if (md.lattice.plain_fcc())
      return md::measure_atom_steps_per_second(pot, o, md::fcc_equilibrium(pot).lattice_constant, md.cells,
                                               md.temperature, md.seed, md.dt);
    particles::LatticeSpec spec = md.lattice;
    spec.constant = a0;
    return md::measure_atom_steps_per_second(pot, o, spec, md.cells, md.temperature, md.seed, md.dt);
  } catch (const std::exception&) {
    return 0.0;  // the run itself reports what is wrong with the box
  }
}

std::string MdClosureModel::build_note() const {
  const std::string npt = md.prepare == BoxPrepare::npt && !md.prepared
                              ? fmt::format("relaxing one box by NPT at {} K, 0 GPa ({} steps), then ", md.temperature,
                                            md.prepare_steps)
                              : std::string();
  return fmt::format("{}building the MD box of every point ({} atoms each, section 6.2)...", npt,
                     md.atoms_per_point());
}
std::vector<std::string> MdClosureModel::check_notes() const {
  const auto& o = md.lattice.orient;
  std::vector<std::string> r{fmt::format(
      "each point's box: {} tiles of {} ({} atoms), x [{}], y [{}], z [{}], at {:.6f} A (the potential's 0 K lattice)",
      md.cells, particles::lattice_name(md.lattice.style), md.atoms_per_point(), fmt::join(o[0], " "),
      fmt::join(o[1], " "), fmt::join(o[2], " "), a0)};
  r.push_back(fmt::format("the boxes' 0 K constants (box frame, {}): C11 = {:.6g}, C12 = {:.6g}, C44 = {:.6g}, "
                          "density {:.6g}; lattice: {}",
                          md.units.name, c11, c12, c44, rho, lattice_from));
  for (const std::string& w : warnings) r.push_back("warning: " + w);
  if (md.prepare == BoxPrepare::npt && md.prepared)
    r.push_back(fmt::format("prepared by NPT: one box at {} K and 0 GPa for {} steps (Nose-Hoover, Tdamp 0.1 ps, "
                            "isotropic Pdamp 1 ps): every box is built at its mean lattice constant over "
                            "the second half, {:.6f} A (mean {:.4f} GPa, {:.2f} K), and the points take that "
                            "crystal's density, {:.6g} (run.json's md.lattice_constant_A, md.density)",
                            md.temperature, md.prepare_steps, md.prepared->lattice_constant,
                            md.prepared->pressure_gpa, md.prepared->temperature, rho));
  else if (md.prepare == BoxPrepare::npt)
    r.push_back(fmt::format("prepare: one box by NPT at {} K and 0 GPa for {} steps when the run starts (Nose-Hoover, "
                            "Tdamp 0.1 ps, isotropic Pdamp 1 ps; {:.3g} atom-steps): every box is built at its mean "
                            "lattice constant over the second half, and the points take that crystal's density "
                            "(run.json's md.lattice_constant_A, md.density), a little below the 0 K crystal's {:.6g}",
                            md.temperature, md.prepare_steps,
                            static_cast<double>(md.atoms_per_point()) * static_cast<double>(md.prepare_steps), rho));
  return r;
}

std::vector<std::pair<std::string, double>> MdClosureModel::constants() const {
  return {{"c11", c11}, {"c12", c12}, {"c44", c44}, {"density", rho}, {"zero_kelvin_lattice_constant_A", a0}};
}

std::string MdClosureModel::constants_source() const {
  return fmt::format("the 0 K {} crystal of the closure's potential in the box frame (lattice: {})",
                     particles::lattice_name(md.lattice.style), lattice_from);
}

std::shared_ptr<const Model> MdClosureModel::prepared() const {
  if (md.prepare != BoxPrepare::npt || md.prepared || !(md.temperature > 0) || !md::complete(md.potential))
    return nullptr;
  auto r = std::make_shared<MdClosureModel>(*this);
  r->md.prepared = prepare_npt(md::Potential(md.potential), md, a0);
  r->rho *= std::pow(a0 / r->md.prepared->lattice_constant, 3);
  return r;
}

std::unique_ptr<Material<1>> MdClosureModel::make1() const { return std::make_unique<MdClosure<1>>(md); }
std::unique_ptr<Material<2>> MdClosureModel::make2() const { return std::make_unique<MdClosure<2>>(md); }
std::unique_ptr<Material<3>> MdClosureModel::make3() const { return std::make_unique<MdClosure<3>>(md); }

std::shared_ptr<const Model> MdClosureEntry::read(Table& m, const Context& ctx) {
  auto r = std::make_shared<MdClosureModel>();
  auto& md = r->md;
  const auto u = units::unit_system(ctx.units);
  if (u) md.units = *u;
  else
    m.check(false, "model",
            fmt::format("md_closure needs case.units to be one of {}, not '{}'", units::unit_system_names(),
                        ctx.units));
  md.potential = md::read_potential(*m.sub("potential"), ctx.deck_dir);
  auto md_table = m.sub("md");
  Table& s = *md_table;
  // The crystal: md decks' [lattice] keys (lattice for their type), `cells` tiles per axis;
  // with neither lattice nor orient given, the lattice the potential's file declares.
  const bool named = s.has("lattice") || s.has("orient");
  if (s.has("lattice")) r->lattice_from = "the deck's";
  particles::read_crystal_keys(s, "lattice", md.lattice);
  s.check(md.lattice.style != particles::LatticeStyle::b2, "lattice",
          "b2 needs two elements on one lattice; a closure's box is of one element (use fcc, bcc or hcp)");
  if (md.lattice.style == particles::LatticeStyle::b2) md.lattice.style = particles::LatticeStyle::fcc;
  md.cells = s.integer_int("cells", 4, 1, 20);  // fcc along the axes: 4 x cells^3 atoms per point
  // The box's atoms counted from the orientation before anything is built (a tile past
  // particles::kMaxTileAtoms is an orientation problem, said against `orient`).
  if (!md.lattice.plain_fcc() && particles::orient_problem(md.lattice).empty()) {
    const double tile = particles::lattice_tile_atoms(md.lattice);
    const double atoms = tile * md.cells * md.cells * md.cells;
    s.check(atoms <= kMaxAtomsPerPoint, "cells",
            fmt::format("gives {:.0f} atoms per point (a tile of this orientation holds {:.0f}); at most {:.0f} are "
                        "allowed",
                        atoms, tile, kMaxAtomsPerPoint));
    if (!(atoms <= kMaxAtomsPerPoint)) md.lattice = particles::LatticeSpec{};
  } else if (!md.lattice.plain_fcc()) {
    md.lattice = particles::LatticeSpec{};  // the orientation's problem is said; read on with fcc
  }
  md.temperature = s.number("temperature", 0.0);
  s.temperature("temperature", md.temperature);
  md.seed = static_cast<std::uint64_t>(s.integer("seed", 1, 0, std::numeric_limits<std::int64_t>::max()));
  md.dt = s.number("dt", 0.001);
  s.positive("dt", md.dt);
  s.check(md.dt <= 0.01, "dt", "is above 0.01 ps; metal MD needs about 0.001 ps");
  md.relax_steps = s.integer("relax_steps", 0, 0, std::numeric_limits<int>::max());  // one advance of the box
  // "npt": one box relaxed at (temperature, 0 GPa) sets every box's lattice constant.
  md.prepare = s.choice("prepare", {"lattice", "npt"}, "lattice") == "npt" ? BoxPrepare::npt : BoxPrepare::lattice;
  md.prepare_steps = s.integer("prepare_steps", 10000, 2, 100000000);
  s.check(md.prepare == BoxPrepare::npt || !s.has("prepare_steps"), "prepare_steps",
          "has no use without prepare = \"npt\"");
  s.check(md.prepare != BoxPrepare::npt || md.temperature > 0, "prepare",
          "npt needs material.md.temperature > 0 (its thermostat's target); at 0 K the 0 K lattice is the one");
  md.sample = s.choice("stress", {"last", "average"}, "last") == "last" ? multiscale::StressSample::last
                                                                        : multiscale::StressSample::average;
  md.skin = s.number("skin", 1.0);
  s.non_negative("skin", md.skin);
  md.mixed_precision = s.choice("precision", {"double", "mixed"}, "double") == "mixed";
  md.deformation = s.choice("deformation", {"boundary", "affine"}, "boundary") == "affine" ? md::Deformation::affine
                                                                                       : md::Deformation::boundary;
  if (s.has("energy_consistency")) md.energy_consistency = s.boolean("energy_consistency", true) ? 1 : 0;
  // [material.md.share]: boxes shared by history (multiscale/box_groups.hpp).
  auto share_table = s.optional_sub("share");
  Table& share = *share_table;
  md.share.enabled = share.boolean("enabled", md.share.enabled);
  md.share.tolerance = share.number("tolerance", md.share.tolerance);
  share.non_negative("tolerance", md.share.tolerance);
  md.share.audit = share.integer_int("audit", md.share.audit, 0, 1000);
  md.share.by_state = share.boolean("by_state", md.share.by_state);
  md.share.state_stress = share.number("state_stress", md.share.state_stress);
  share.positive("state_stress", md.share.state_stress);
  md.share.state_energy = share.number("state_energy", md.share.state_energy);
  share.positive("state_energy", md.share.state_energy);
  md.share.seed = md.seed;
  // The crystal's constants from the potential, once every key of the deck is read (the
  // reader's `later`). prepare = npt's NPT box is the run's to run (prepared()), not the
  // reading's: a check states it, and a large prepare_steps holds up no check.
  auto crystal = [r, named](Table& table) {
    if (!md::complete(r->md.potential)) return;  // read_potential said why
    try {
      const md::Potential pot(r->md.potential);
      if (!named)
        if (const auto d = md::declared_lattice(pot, 0)) {
          r->md.lattice.style = d->style;
          r->lattice_from = "the one the potential's file declares";
        }
      if (named)
        if (const std::string w = md::lattice_contradiction(pot, 0, r->md.lattice.style, 0.0); !w.empty())
          r->warnings.push_back(w);
      const auto props = md_closure_properties(r->md.potential, r->md.units, r->md.lattice);
      r->rho = props.density;
      r->c11 = props.modulus;
      r->c12 = props.c12;
      r->c44 = props.c44;
      r->a0 = props.equilibrium.lattice_constant;
      // A crystal the potential does not hold together gives boxes that fall apart: its
      // full tensor at 0 K must be Born-stable (md/elastic_constants.hpp).
      particles::LatticeSpec at = r->md.lattice;
      at.constant = r->a0;
      const md::ElasticTensor t = md::elastic_tensor(pot, at, md::equilibrium_tiles(at));
      const auto& k = t.crystal;
      table.check(md::born_stable(t.crystal), "md",
                  fmt::format("its {} crystal (lattice: {}) is not Born-stable under this potential: C11 = {:.4g}, "
                              "C12 = {:.4g}, C44 = {:.4g} GPa in the crystal's axes at a = {:.6f} A; name "
                              "material.md.lattice as the element's crystal",
                              particles::lattice_name(at.style), r->lattice_from, k[0][0], k[0][1], k[3][3], r->a0));
      // its atoms per A^3 (the budget takes another crystal as the fcc box of its atoms)
      r->number_density = static_cast<double>(r->md.atoms_per_point()) / box_volume(r->md, r->a0);
      r->cutoff = props.cutoff;
      r->md.stiffness = md_closure_stiffness(pot, r->md.lattice, r->a0);
    } catch (const std::exception& e) {
      table.check(false, "potential", e.what());
    }
  };
  if (ctx.later) ctx.later(crystal);
  else crystal(m);
  return r;
}

std::optional<material::Crystal> potential_crystal(Table& table, std::string_view key, const std::string& deck_dir,
                                                   const std::string& units) {
  const auto u = units::unit_system(units);
  if (!u) return std::nullopt;  // the caller names the missing units
  const md::PotentialSpec spec = md::read_potential(*table.sub(key), deck_dir);
  // The crystal: `lattice` where the deck names it, else the one the potential's file
  // declares for its element, else fcc. A cubic law takes a cubic crystal's constants.
  const bool named = table.has("lattice");
  const std::string style = table.choice("lattice", {"fcc", "bcc"}, "fcc");
  if (!md::complete(spec)) return std::nullopt;  // read_potential said why
  try {
    const md::Potential pot(spec);
    particles::LatticeSpec lattice;
    lattice.style = particles::lattice_style(style);
    std::string why = named ? "the deck's lattice" : "fcc: the file declares no lattice";
    const auto declared = md::declared_lattice(pot, 0);
    if (!named && declared) {
      if (declared->style == particles::LatticeStyle::hcp) {
        table.check(false, "lattice",
                    fmt::format("is not given, and the potential's file declares {} hcp: cubic_elastic needs a cubic "
                                "crystal (name lattice = \"fcc\" or \"bcc\" to take that one's constants)",
                                pot.eam()->type_names()[0]));
        return std::nullopt;
      }
      lattice.style = declared->style;
      why = "the lattice the potential's file declares";
    }
    const auto props = md_closure_properties(spec, *u, lattice);
    material::Crystal c{props.density, props.modulus, props.c12, props.c44, {}, {}};
    c.source = fmt::format("the 0 K {} crystal of {} at a = {:.6f} A, the potential's minimum ({})",
                           particles::lattice_name(lattice.style), pot.describe(),
                           props.equilibrium.lattice_constant, why);
    if (const std::string w = md::lattice_contradiction(pot, 0, lattice.style, 0.0); !w.empty())
      c.warnings.push_back(w);
    return c;
  } catch (const std::exception& e) {
    table.check(false, key, e.what());
  }
  return std::nullopt;
}

}  // namespace mpmx::multiscale
