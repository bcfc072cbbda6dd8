#include "mpmx/dpd/config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <fmt/format.h>

#include "mpmx/core/units.hpp"

namespace mpmx::dpd {

namespace {

bool read_vec3(io::Section& s, std::string_view key, md::Vec3& out, bool required) {
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

DpdConfig read_dpd_config(io::Deck& deck) {
  DpdConfig c;
  c.deck_file = deck.name();
  auto root = deck.root();

  auto cs = root.table("case");
  c.id = cs.string("id");
  c.title = cs.string("title", "");
  c.seed_ref = cs.string("seed", "");

  c.potential = read_pair_potential(root.table("potential"),
                                    std::filesystem::path(deck.name()).parent_path().string());
  const double rc = cutoff(c.potential);

  // Particles.
  std::set<std::string> group_names;
  auto blocks = root.tables("block");
  if (blocks.empty()) root.check(false, "block", "at least one [[block]] of particles is needed");
  md::Vec3 extent{0, 0, 0};
  bool all_fcc = true;
  for (auto& b : blocks) {
    BlockSpec s;
    s.fcc = b.choice("lattice", {"fcc", "random"}, "fcc") == "fcc";
    if (s.fcc) {
      s.constant = b.number("constant");
      b.positive("constant", s.constant);
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
      s.count = static_cast<long>(b.integer("count"));
      b.check(s.count >= 1 && s.count <= 100000000, "count", "must be from 1 to 1e8");
      read_vec3(b, "size", s.size, true);
      for (int d = 0; d < 3; ++d) b.check(s.size[d] > 0, "size", "every edge must be positive");
    }
    read_vec3(b, "origin", s.origin, false);
    s.mass = b.number("mass");
    b.positive("mass", s.mass);
    read_vec3(b, "velocity", s.velocity, false);
    s.group = b.string("group", "");
    if (!s.group.empty()) {
      b.check(group_names.insert(s.group).second, "group", "names a rigid group already defined");
    }
    for (int d = 0; d < 3; ++d) {
      const double top = s.origin[d] + (s.fcc ? s.cells[d] * s.constant : s.size[d]);
      extent[d] = std::max(extent[d], top);
    }
    all_fcc = all_fcc && s.fcc;
    c.blocks.push_back(s);
  }
  for (auto& r : root.tables("rigid")) {
    RegionGroupSpec g;
    g.name = r.string("name");
    r.check(!g.name.empty() && group_names.insert(g.name).second, "name",
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

  // Domain.
  auto box = root.optional_table("box");
  md::Vec3 size = extent;
  if (box.has("size")) read_vec3(box, "size", size, true);
  else box.check(all_fcc, "size", "is needed when a block is a random fill");
  for (int d = 0; d < 3; ++d) box.check(size[d] > 0, "size", "every edge must be positive");
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

  // DPD(E).
  auto dp = root.table("dpd");
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
  dp.non_negative("temperature", p.temperature);
  c.initial_temperature = dp.number("initial_temperature", p.temperature);
  dp.non_negative("initial_temperature", c.initial_temperature);
  if (p.energy_conserving) {
    const double cv = dp.number("heat_capacity_kB");
    dp.positive("heat_capacity_kB", cv);
    p.heat_capacity = cv * units::boltzmann_eV_per_K;
  }
  const auto seed = dp.integer("seed", 1);
  dp.check(seed >= 0, "seed", "must be >= 0");
  p.seed = static_cast<std::uint64_t>(seed);

  auto eq = root.optional_table("equilibrate");
  if (eq.present()) {
    c.equilibrate = true;
    c.berendsen.temperature = eq.number("temperature", p.temperature);
    eq.positive("temperature", c.berendsen.temperature);
    c.berendsen.tau = eq.number("tau");
    eq.positive("tau", c.berendsen.tau);
    c.equilibrate_steps = eq.integer("steps");
    eq.check(c.equilibrate_steps >= 0, "steps", "must be >= 0");
  }

  auto run = root.table("run");
  c.dt = run.number("dt");
  run.positive("dt", c.dt);
  run.check(c.dt <= 1.0, "dt", "is above 1 ps: DPD time steps in metal units are 0.001-0.1 ps");
  if (c.equilibrate)
    eq.check(c.berendsen.tau >= c.dt, "tau", fmt::format("must be at least the time step run.dt = {} ps", c.dt));
  c.steps = run.integer("steps");
  run.check(c.steps >= 0, "steps", "must be >= 0");
  c.thermo = run.integer("thermo", 100);
  run.check(c.thermo >= 1, "thermo", "must be >= 1");
  c.dump_every = run.integer("dump_every", 0);
  run.check(c.dump_every >= 0 && (c.dump_every == 0 || c.dump_every % c.thermo == 0), "dump_every",
            "must be 0 (no dump) or a multiple of thermo");
  c.skin = run.number("skin", 1.0);
  run.non_negative("skin", c.skin);
  deck.finish();
  return c;
}

}  // namespace mpmx::dpd
