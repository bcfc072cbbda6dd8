#include "mpmx/app/dpd/config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include <fmt/format.h>

#include "mpmx/app/case_table.hpp"
#include "mpmx/app/dpd/budget.hpp"
#include "mpmx/core/checked_count.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/file_text.hpp"
#include "mpmx/core/machine.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::app::dpd {

namespace {

constexpr std::int64_t kMaxSteps = std::numeric_limits<std::int64_t>::max();
// Lengths a deck may give, in Angstrom: a coarse lattice constant (the seed's is 7.3) and
// a block's size and place (a millimetre), so that the extents stay finite.
constexpr double kMaxLatticeConstant = 1000.0;
constexpr double kMaxLength = 1e7;

bool read_vec3(io::Section& s, std::string_view key, particles::Vec3& out, bool required) {
  if (!required && !s.has(key)) return false;
  const auto v = s.numbers(key);
  if (v.size() != 3) {
    if (s.has(key)) s.check(false, key, "expected three numbers [x, y, z]");
    return false;
  }
  std::copy(v.begin(), v.end(), out.begin());
  return true;
}

}  // namespace

PairPotential read_potential(io::Section s, const std::string& deck_dir) {
  if (s.has("file")) {
    s.check(!s.has("style"), "style", "give either file or style and parameters, not both");
    std::filesystem::path path = s.string("file");
    if (path.is_relative() && !deck_dir.empty()) path = deck_dir / path;
    try {
      io::Deck d = io::Deck::from_file(path.string(), "potential file");
      io::Section inner = d.root().table("potential");
      inner.check(!inner.has("file"), "file", "a potential file cannot name another");
      PairPotential p = inner.has("file") ? PairPotential{} : read_pair_potential(inner);
      d.finish();
      return p;
    } catch (const InputError& e) {
      s.check(false, "file", e.what());
      return PairPotential{};
    }
  }
  return read_pair_potential(s);
}

namespace {

// [[track]], [analysis], [tensile], [profile] (analysis.hpp); `groups` the rigid groups' names.
void read_analysis(io::Section& root, DpdConfig& c, const std::set<std::string>& groups) {
  AnalysisSpec& a = c.analysis;
  auto an = root.optional_table("analysis");
  read_track_settings(root, an, c.thermo, a);
  a.cna_lattice = an.number("cna_lattice", 0.0);
  an.non_negative("cna_lattice", a.cna_lattice);
  auto te = root.optional_table("tensile");
  if (te.present()) {
    const auto g = te.strings("grips", {});
    if (g.size() == 2 && g[0] != g[1] && groups.count(g[0]) && groups.count(g[1])) a.grips = {g[0], g[1]};
    else te.check(false, "grips", "expected the names of two different rigid groups [left, right]");
    const auto r = te.numbers("slope_strain", {0.0, 0.05});
    if (r.size() == 2 && r[1] > r[0]) a.slope_strain = {r[0], r[1]};
    else te.check(false, "slope_strain", "expected [lower, upper] strains with upper > lower");
  }
}

// The run's memory, roughly: per particle its fields and its share of the neighbour list
// and pair-force buffer (about 1.5 KiB at the seed's 12 Angstrom cutoff and density, 49
// pairs a particle within cutoff + skin), or per pair 32 bytes (list, owner and sweep
// slots, force buffer) where the blocks are denser than the seed's (a constant of 0.5 A
// under a 12 A cutoff: 150,000 pairs a particle); and the grid's node fields; refused
// with the figure when it exceeds the machine's memory.
void check_memory(io::Section& root, const DpdConfig& c) {
  const double particles = block_particles(c);
  double bytes = std::max(1536.0 * particles, 32.0 * block_pairs(c));
  if (c.grid.cell > 0) {
    double nodes = 1;
    const double size[3] = {c.domain.box.lx, c.domain.box.ly, c.domain.box.lz};
    for (int d = 0; d < 3; ++d) {
      const double cells = (size[d] + 2 * c.grid.margin) / c.grid.cell;
      root.check(cells <= 4096, "grid",
                 fmt::format("cell = {} A and margin = {} A make {:.0f} cells along axis {} (at most 4096)", c.grid.cell,
                             c.grid.margin, std::ceil(cells), d));
      nodes *= cells + 3;
    }
    bytes += 16 * 8 * nodes;
    root.check(nodes <= 4e9, "grid", fmt::format("cell = {} A makes {:.3g} grid nodes (at most 4e9)", c.grid.cell, nodes));
  }
  root.check(particles <= 1e8, "block", fmt::format("the blocks hold {:.3g} particles (at most 1e8)", particles));
  const double have = static_cast<double>(physical_memory_bytes());
  if (have > 0)
    root.check(bytes <= 0.8 * have, "block",
               fmt::format("{:.3g} particles ({:.3g} pairs within cutoff + skin){} need about {}, more than 80% of "
                           "this machine's {}",
                           particles, block_pairs(c), c.grid.cell > 0 ? " and their grid" : "", format_bytes(bytes),
                           format_bytes(have)));
}

// [grid] and [continuum].
void read_coupling(io::Section& root, DpdConfig& c) {
  auto g = root.optional_table("grid");
  if (g.present()) {
    c.grid.cell = g.number("cell");
    g.positive("cell", c.grid.cell);
    g.check(c.grid.cell < cutoff(c.potential), "cell",
            fmt::format("must be below the pair potential's cutoff {} A (seed 004 sec. 3: the DPD cutoff exceeds "
                        "the cell edge)", cutoff(c.potential)));
    c.grid.margin = g.number("margin", 30.0);
    g.non_negative("margin", c.grid.margin);
    g.check(!c.domain.periodic[0] && !c.domain.periodic[1] && !c.domain.periodic[2], "cell",
            "the DPD/MPM grid needs open boundaries (box.boundary = [\"f\", \"f\", \"f\"])");
  }
  auto m = root.optional_table("continuum");
  if (m.present()) {
    multiscale::ContinuumSpec& s = c.continuum;
    s.on = true;
    root.check(c.grid.cell > 0, "continuum", "a concurrent DPD/MPM run needs [grid] cell");
    const auto x = m.numbers("x");
    if (x.size() == 2 && x[1] > x[0]) s.lo = x[0], s.hi = x[1];
    else m.check(false, "x", "expected [lower, upper] with upper > lower (Angstrom)");
    s.lattice_constant = m.number("lattice_constant");
    m.check(s.lattice_constant >= 0.05 * cutoff(c.potential) && s.lattice_constant <= 1000, "lattice_constant",
            fmt::format("must lie in [{:.3g}, 1000] Angstrom (at least a twentieth of the pair cutoff)",
                        0.05 * cutoff(c.potential)));
    s.from_potential = m.choice("constants_from", {"pair_potential", "given"}, "pair_potential") == "pair_potential";
    s.pair_reaction = m.choice("interface", {"pair_reaction", "seed"}, "pair_reaction") == "pair_reaction";
    if (!s.from_potential) {
      s.c11 = m.number("c11"), s.c12 = m.number("c12"), s.c44 = m.number("c44");
      m.positive("c11", s.c11), m.positive("c44", s.c44);
      m.check(s.c11 > std::abs(s.c12) && s.c11 + 2 * s.c12 > 0, "c12", "C11 > |C12| and C11 + 2 C12 > 0 (Born stability)");
    }
  }
}

// One [[block]]; `groups`: the rigid groups' names so far (the block's own is added).
BlockSpec read_block(io::Section& b, std::set<std::string>& groups) {
  BlockSpec s;
  s.fcc = b.choice("lattice", {"fcc", "random"}, "fcc") == "fcc";
  if (s.fcc) {
    s.constant = b.number("constant");
    b.check(s.constant > 0 && s.constant <= kMaxLatticeConstant, "constant",
            fmt::format("must lie in (0, {}] Angstrom", kMaxLatticeConstant));
    const auto cells = b.numbers("cells");
    if (cells.size() == 3) {
      for (int d = 0; d < 3; ++d) {
        b.check(cells[d] >= 1 && cells[d] <= 1000 && cells[d] == std::floor(cells[d]), "cells",
                "each entry must be a whole number of unit cells from 1 to 1000");
        s.cells[d] = static_cast<int>(std::clamp(cells[d], 1.0, 1000.0));
      }
    } else {
      b.check(false, "cells", "expected [nx, ny, nz]");
    }
  } else {
    s.count = b.integer("count", 1, 100000000);
    read_vec3(b, "size", s.size, true);
    for (int d = 0; d < 3; ++d)
      b.check(s.size[d] > 0 && s.size[d] <= kMaxLength, "size",
              fmt::format("every edge must lie in (0, {:g}] Angstrom", kMaxLength));
  }
  read_vec3(b, "origin", s.origin, false);
  for (int d = 0; d < 3; ++d)
    b.check(std::abs(s.origin[d]) <= kMaxLength, "origin", fmt::format("must lie within {:g} Angstrom of 0", kMaxLength));
  s.mass = b.number("mass");
  b.positive("mass", s.mass);
  read_vec3(b, "velocity", s.velocity, false);
  s.group = b.string("group", "");
  if (!s.group.empty()) {
    b.check(groups.insert(s.group).second, "group", "names a rigid group already defined");
  }
  s.free = b.boolean("free", false);
  b.check(!s.free || !s.group.empty(), "free", "only a rigid group (group = \"name\") moves as a free body");
  return s;
}

// [[rigid]]: rigid groups by region; `groups` as read_block's.
void read_regions(io::Section& root, DpdConfig& c, std::set<std::string>& groups) {
  for (auto& r : root.tables("rigid")) {
    RegionGroupSpec g;
    g.name = r.string("name");
    r.check(!g.name.empty() && groups.insert(g.name).second, "name",
            "must be a new, non-empty rigid group name");
    static const char* axes[3] = {"x", "y", "z"};
    bool any = false;
    for (int d = 0; d < 3; ++d) {
      if (!r.has(axes[d])) continue;
      const auto v = r.numbers(axes[d]);
      if (v.size() == 2 && v[1] > v[0]) {
        g.lo[d] = v[0], g.hi[d] = v[1];
        any = true;
      } else {
        r.check(false, axes[d], "expected [lower, upper] with upper > lower (Angstrom)");
      }
    }
    r.check(any, "x", "a rigid region needs at least one of x, y, z = [lower, upper]");
    read_vec3(r, "velocity", g.velocity, false);
    c.regions.push_back(g);
  }
}

// [box]: the domain's size (the blocks' extent unless given) and boundaries.
void read_domain(io::Section& root, const particles::Vec3& extent, bool all_fcc, DpdConfig& c) {
  auto box = root.optional_table("box");
  particles::Vec3 size = extent;
  if (box.has("size")) read_vec3(box, "size", size, true);
  else box.check(all_fcc, "size", "is needed when a block is a random fill");
  for (int d = 0; d < 3; ++d)
    box.check(size[d] > 0 && size[d] <= 2 * kMaxLength, "size",
              fmt::format("every edge must lie in (0, {:g}] Angstrom", 2 * kMaxLength));
  c.domain.box.lx = size[0], c.domain.box.ly = size[1], c.domain.box.lz = size[2];
  const auto bnd = box.strings("boundary", {"p", "p", "p"});
  if (bnd.size() == 3) {
    for (int d = 0; d < 3; ++d) {
      box.check(bnd[d] == "p" || bnd[d] == "f", "boundary", "each entry is \"p\" (periodic) or \"f\" (open)");
      c.domain.periodic[d] = bnd[d] == "p";
    }
  } else {
    box.check(false, "boundary", "expected three entries, e.g. [\"p\", \"p\", \"f\"]");
  }
}

// [dpd]: the ensemble, the integrator and the DPD(E) parameters; `rc` the pair cutoff.
void read_dpd_params(io::Section& dp, double rc, DpdConfig& c) {
  DpdParams& p = c.params;
  p.energy_conserving = dp.choice("ensemble", {"dpd", "dpde"}, "dpd") == "dpde";
  p.integrator = dp.choice("integrator", {"shardlow", "velocity_verlet"}, "shardlow") == "shardlow"
                     ? Integrator::shardlow
                     : Integrator::velocity_verlet;
  dp.check(!(p.energy_conserving && p.integrator != Integrator::shardlow), "integrator",
           "DPDE (ensemble = \"dpde\") needs integrator = \"shardlow\"");
  p.gamma = dp.number("gamma");
  dp.non_negative("gamma", p.gamma);
  p.cutoff = dp.number("cutoff", rc);
  dp.positive("cutoff", p.cutoff);
  p.temperature = dp.number("temperature");
  dp.temperature("temperature", p.temperature);
  c.initial_temperature = dp.number("initial_temperature", p.temperature);
  dp.temperature("initial_temperature", c.initial_temperature);
  if (p.energy_conserving) {
    const double cv = dp.number("heat_capacity_kB");
    dp.positive("heat_capacity_kB", cv);
    p.heat_capacity = cv * units::boltzmann_eV_per_K;
  }
  const auto seed = dp.integer("seed", 1, 0, kMaxSteps);
  p.seed = static_cast<std::uint64_t>(seed);
}

// The pair forces' reach on every periodic axis: at most half the box, so that a particle
// meets each other particle through one image at most and never its own (whose random
// force, drawn per image, no dissipation balances: a cutoff of 60 A in a 79 A box heated
// a fluid to 1e29 K).
void check_reach_in_box(io::Section& root, const DpdConfig& c) {
  const double reach = std::max(cutoff(c.potential), c.params.cutoff);
  static const char* axes[3] = {"x", "y", "z"};
  for (int d = 0; d < 3; ++d)
    if (c.domain.periodic[d] && !(reach <= 0.5 * c.domain.length(d))) {
      root.error(fmt::format("box: the pair cutoff {:.6g} A exceeds half the periodic length along {} ({:.6g} A): "
                             "a particle would meet another through two images or itself; make the box at least "
                             "{:.6g} A along {} or the axis open (\"f\")",
                             reach, axes[d], c.domain.length(d), 2 * reach, axes[d]));
      return;
    }
}

// [equilibrate] and [run].
void read_run(io::Section& root, DpdConfig& c) {
  const DpdParams& p = c.params;
  auto eq = root.optional_table("equilibrate");
  if (eq.present()) {
    c.equilibrate = true;
    c.berendsen.temperature = eq.number("temperature", p.temperature);
    eq.positive("temperature", c.berendsen.temperature);
    eq.temperature("temperature", c.berendsen.temperature);
    c.berendsen.tau = eq.number("tau");
    eq.positive("tau", c.berendsen.tau);
    c.equilibrate_steps = eq.integer("steps", 0, kMaxSteps);
  }

  auto run = root.table("run");
  c.dt = run.number("dt");
  run.positive("dt", c.dt);
  run.check(c.dt <= 1.0, "dt", "is above 1 ps: DPD time steps in metal units are 0.001-0.1 ps");
  if (c.equilibrate)
    eq.check(c.berendsen.tau >= c.dt, "tau", fmt::format("must be at least the time step run.dt = {} ps", c.dt));
  c.steps = run.integer("steps", 0, kMaxSteps);
  // The run counts its steps from the start of the equilibration.
  eq.check(checked_sum(c.equilibrate ? c.equilibrate_steps : 0, c.steps).has_value(), "steps",
           "plus run.steps is more steps than a run can count (2^63 - 1)");
  // The system advances thermo steps at a time in an int.
  c.thermo = run.integer("thermo", 100, 1, std::numeric_limits<int>::max());
  c.dump_every = run.integer("dump_every", 0, 0, kMaxSteps);
  run.check(c.dump_every == 0 || c.dump_every % c.thermo == 0, "dump_every",
            "must be 0 (no dump) or a multiple of thermo");
  c.skin = run.number("skin", 1.0);
  // A skin beyond the cutoff only multiplies the listed pairs ((rc + skin)^3 / rc^3: 1000
  // with the seed's 12 A ran out of memory, 1e200 lost every force to rounding).
  run.check(c.skin >= 0 && c.skin <= cutoff(c.potential), "skin",
            fmt::format("must lie in [0, {}] Angstrom (the pair cutoff)", cutoff(c.potential)));
}

}  // namespace

DpdConfig read_dpd_config(io::Deck& deck) {
  DpdConfig c;
  c.deck_file = deck.name();
  auto root = deck.root();

  const CaseTable cs = read_case_table(root, deck.name(), true, "metal");
  c.id = cs.id;  // printed on progress and result lines
  c.title = cs.title;
  c.seed_ref = cs.seed;

  c.potential = read_potential(root.table("potential"), std::filesystem::path(deck.name()).parent_path().string());
  const double rc = cutoff(c.potential);

  // Particles.
  std::set<std::string> group_names;
  auto blocks = root.tables("block");
  if (blocks.empty()) root.check(false, "block", "at least one [[block]] of particles is needed");
  particles::Vec3 extent{0, 0, 0};
  bool all_fcc = true;
  for (auto& b : blocks) {
    c.blocks.push_back(read_block(b, group_names));
    const BlockSpec& s = c.blocks.back();
    for (int d = 0; d < 3; ++d) {
      const double top = s.origin[d] + (s.fcc ? s.cells[d] * s.constant : s.size[d]);
      extent[d] = std::max(extent[d], top);
    }
    all_fcc = all_fcc && s.fcc;
  }
  read_regions(root, c, group_names);
  read_domain(root, extent, all_fcc, c);
  auto dp = root.table("dpd");
  read_dpd_params(dp, rc, c);
  read_run(root, c);
  check_reach_in_box(root, c);
  read_analysis(root, c, group_names);
  read_coupling(root, c);
  check_memory(root, c);
  deck.finish();
  return c;
}

}  // namespace mpmx::app::dpd
