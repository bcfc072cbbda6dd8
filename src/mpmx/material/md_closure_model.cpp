#include "mpmx/material/md_closure_model.hpp"

#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/config.hpp"

namespace mpmx::material {

double MdClosureModel::wave_speed(int, double density, double) const { return std::sqrt(c11 / density); }
std::unique_ptr<Material<1>> MdClosureModel::make1() const { return std::make_unique<MdClosure<1>>(md); }
std::unique_ptr<Material<2>> MdClosureModel::make2() const { return std::make_unique<MdClosure<2>>(md); }
std::unique_ptr<Material<3>> MdClosureModel::make3() const { return std::make_unique<MdClosure<3>>(md); }

std::shared_ptr<const Model> read_md_closure(io::Section& m, const Context& ctx) {
  auto r = std::make_shared<MdClosureModel>();
  auto& md = r->md;
  const auto u = units::unit_system(ctx.units);
  if (u) md.units = *u;
  else
    m.check(false, "model",
            fmt::format("md_closure needs case.units to be one of {}, not '{}'", units::unit_system_names(),
                        ctx.units));
  md.potential = md::read_potential(m.table("potential"), ctx.deck_dir);
  io::Section s = m.table("md");
  md.cells = static_cast<int>(s.integer("cells", 4));
  s.check(md.cells >= 1 && md.cells <= 20, "cells", "must be from 1 to 20 (4 x cells^3 atoms per point)");
  md.temperature = s.number("temperature", 0.0);
  s.temperature("temperature", md.temperature);
  const auto seed = s.integer("seed", 1);
  s.check(seed >= 0, "seed", "must be >= 0");
  md.seed = static_cast<std::uint64_t>(seed);
  md.dt = s.number("dt", 0.001);
  s.positive("dt", md.dt);
  s.check(md.dt <= 0.01, "dt", "is above 0.01 ps; metal MD needs about 0.001 ps");
  md.relax_steps = s.integer("relax_steps", 0);
  s.check(md.relax_steps >= 0, "relax_steps", "must be >= 0");
  md.sample = s.choice("stress", {"last", "average"}, "last") == "last" ? multiscale::StressSample::last
                                                                        : multiscale::StressSample::average;
  md.skin = s.number("skin", 1.0);
  s.non_negative("skin", md.skin);
  md.mixed_precision = s.choice("precision", {"double", "mixed"}, "double") == "mixed";
  if (s.has("energy_consistency")) md.energy_consistency = s.boolean("energy_consistency", true) ? 1 : 0;
  if (md.potential.style != "eam" || !md.potential.file.empty()) {
    try {
      const auto props = md_closure_properties(md.potential, md.units);
      r->rho = props.density;
      r->c11 = props.modulus;
    } catch (const std::exception& e) {
      m.check(false, "potential", e.what());
    }
  }
  return r;
}

}  // namespace mpmx::material
