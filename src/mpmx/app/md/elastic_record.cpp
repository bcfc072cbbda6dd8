#include "mpmx/app/md/elastic_record.hpp"

#include <fmt/format.h>

#include "mpmx/md/elastic_constants.hpp"
#include "mpmx/md/equilibrium.hpp"
#include "mpmx/multiscale/strained_box.hpp"

namespace mpmx::app::md {

namespace {

toml::array rows(const Voigt& c) {
  toml::array out;
  for (const auto& row : c) {
    toml::array r;
    for (double v : row) r.push_back(v);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

ElasticRecord elastic_record(const MdConfig& c, const Potential& pot) {
  particles::LatticeSpec spec = c.lattice;
  if (c.elastic_at_minimum) spec.constant = lattice_equilibrium(pot, spec).lattice_constant;
  ElasticTensor t;
  Voigt error{};
  const bool hot = c.elastic_temperature > 0;
  if (hot) {
    // The deck's box (its cells): thermal fluctuations average down with its atoms.
    multiscale::StrainedBoxOptions o;
    o.temperature = c.elastic_temperature;
    o.strain = c.elastic_strain;
    o.dt = c.dt;
    o.equilibrate_steps = c.elastic_equilibrate_steps;
    o.sample_steps = c.elastic_sample_steps;
    o.seed = c.seed;
    o.threads = c.options.threads;
    const auto hot_t = multiscale::md_strained_tensor(pot, spec, c.cells, o);
    t.box = hot_t.c;
    t.stress = hot_t.stress;
    t.strain = hot_t.strain;
    t.crystal = rotate_to_crystal(t.box, orientation_matrix(spec));
    error = hot_t.error;  // of the box frame's entries
  } else {
    ElasticOptions o;
    o.strain = c.elastic_strain;
    o.relax = c.elastic_relax;
    t = elastic_tensor(pot, spec, equilibrium_tiles(spec), o);
  }
  const auto& k = t.crystal;
  ElasticRecord r;
  toml::array stress;
  for (double s : t.stress) stress.push_back(s);
  r.table = toml::table{{"lattice", particles::lattice_name(spec.style)},
                        {"lattice_constant_A", spec.constant},
                        {"at", c.elastic_at_minimum ? "the potential's 0 K minimum" : "[lattice].constant"},
                        {"strain", t.strain},
                        {"relaxed", t.relaxed},
                        {"largest_force_eV_A", t.largest_force},
                        {"order", "Voigt: xx yy zz yz xz xy; GPa"},
                        {"box_frame_GPa", rows(t.box)},
                        {"crystal_axes_GPa", rows(t.crystal)},
                        {"stress_GPa", std::move(stress)},
                        {"born_stable", born_stable(t.crystal)},
                        {"temperature_K", c.elastic_temperature}};
  if (hot) r.table.insert("box_frame_error_GPa", rows(error));
  // The box's errors are the crystal's where the box is along the crystal's axes.
  const bool along_axes = spec.orient == particles::kCubeAxes;
  auto pm = [&](int i, int j) { return hot && along_axes ? fmt::format(" +- {:.1f}", error[i][j]) : std::string(); };
  const std::string stable = born_stable(t.crystal) ? "Born-stable" : "NOT Born-stable: not this potential's crystal";
  if (spec.style == particles::LatticeStyle::hcp) {
    r.table.insert("hexagonal", toml::table{{"c11", k[0][0]}, {"c12", k[0][1]}, {"c13", k[0][2]},
                                            {"c33", k[2][2]}, {"c44", k[3][3]}, {"c66", k[5][5]}});
    r.summary = fmt::format("elastic, hcp at a = {:.6f} A ({}): C11 {:.2f}{}, C12 {:.2f}{}, C13 {:.2f}{}, C33 {:.2f}{}, "
                            "C44 {:.2f}{}, C66 {:.2f}{} GPa, {}",
                            spec.constant,
                            hot ? fmt::format("{:g} K", c.elastic_temperature) : t.relaxed ? "relaxed" : "unrelaxed",
                            k[0][0], pm(0, 0), k[0][1], pm(0, 1), k[0][2], pm(0, 2), k[2][2], pm(2, 2), k[3][3],
                            pm(3, 3), k[5][5], pm(5, 5), stable);
  } else {
    r.table.insert("cubic", toml::table{{"c11", k[0][0]}, {"c12", k[0][1]}, {"c44", k[3][3]}});
    r.summary = fmt::format("elastic, {} at a = {:.6f} A{}: C11 {:.2f}{}, C12 {:.2f}{}, C44 {:.2f}{} GPa (cube axes), {}",
                            particles::lattice_name(spec.style), spec.constant,
                            hot ? fmt::format(" and {:g} K", c.elastic_temperature) : std::string(), k[0][0], pm(0, 0),
                            k[0][1], pm(0, 1), k[3][3], pm(3, 3), stable);
  }
  return r;
}

}  // namespace mpmx::app::md
