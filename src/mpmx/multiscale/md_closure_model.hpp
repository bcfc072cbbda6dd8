#pragma once
// The [material] table of model = "md_closure": [material.potential] and
// [material.md]. The crystal's density and C11 (continuum units) come from the
// potential itself.
#include <optional>
#include <string_view>

#include "mpmx/material/model.hpp"
#include "mpmx/multiscale/md_closure.hpp"

namespace mpmx::multiscale {

struct MdClosureModel final : material::Model {
  MdClosureConfig md;
  double rho = 1.0, c11 = 1.0;   // the unstrained crystal's, continuum units
  double a0 = 3.615, cutoff = 8.0;  // its lattice constant and the potential's cutoff, Angstrom
  double number_density = 4.0 / (3.615 * 3.615 * 3.615);  // its atoms per A^3
  double c12 = 0.0, c44 = 0.0;      // the box frame's d sigma_yy / d e_xx and shear, continuum units
  std::string lattice_from = "fcc, the default";  // where the boxes' lattice comes from
  std::vector<std::string> warnings;              // what the potential's file contradicts

  std::string name() const override { return "md_closure"; }
  double density() const override { return rho; }
  bool solid() const override { return true; }
  bool density_of_unstrained() const override { return true; }
  double wave_speed(int, double density, double) const override;
  bool per_body() const override { return false; }
  double uniaxial_modulus() const override { return c11; }
  // A continuum step must be a whole number of MD steps.
  std::string time_step_problem(double dt) const override;
  double time_quantum() const override { return md.dt / md.units.time_ps; }
  // From the crystal's uniaxial curve and the Rayleigh line (md/compression_moduli.hpp),
  // along whichever of the dim axes gives the fastest wave.
  Shocked shocked(int dim, double up) const override;
  // The box of a point as it is kept between macro steps (md/budget's kept box), the
  // closure's own records of the point, and its atom-steps: one box per point, the most
  // sharing can cost (it cannot know the groups before the run). The lists and buffers of
  // a box being advanced are per thread (scratch_bytes).
  material::PointCost point_cost(double dt) const override;
  double measured_rate() const;
  double atoms_per_point() const override { return md.atoms_per_point(); }
  // prepare = npt: the law with the NPT box run (md.prepared) and the points' density that
  // crystal's. The deck's reading leaves it to the run, before the points' boxes.
  std::shared_ptr<const material::Model> prepared() const override;
  std::string build_note() const override;
  // The boxes' crystal and, with prepare = npt, the NPT run the run starts with.
  std::vector<std::string> check_notes() const override;
  std::vector<std::pair<std::string, double>> constants() const override;
  std::string constants_source() const override;
  std::unique_ptr<material::Material<1>> make1() const override;
  std::unique_ptr<material::Material<2>> make2() const override;
  std::unique_ptr<material::Material<3>> make3() const override;
};

// The registry entry (app/mpm/materials.hpp).
struct MdClosureEntry {
  static constexpr std::string_view name = "md_closure";
  static std::shared_ptr<const material::Model> read(Table& m, const material::Context& ctx);
};

// The 0 K crystal of the potential in sub-table `key` of `table` (files relative to
// `deck_dir`), in the continuum units `units` names: what Context::crystal_of gives the
// laws whose constants come from a potential (cubic_elastic). Problems are recorded
// against `table` and `key`; nullopt then.
std::optional<material::Crystal> potential_crystal(Table& table, std::string_view key, const std::string& deck_dir,
                                                   const std::string& units);

}  // namespace mpmx::multiscale
