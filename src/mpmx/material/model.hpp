#pragma once
// A material's parameters. A [material] table is read by its model's own reader (the
// entry of its name: a struct with `name` and `read`, core/registry.hpp) into a
// dimension-free Model (the parameters, checked), which then makes the Material of the
// run's dimension. The list of materials is app/mpm/materials.hpp: adding one is its
// own file and one line there.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mpmx/core/table.hpp"
#include "mpmx/material/material.hpp"

namespace mpmx::material {

// The unstrained 0 K crystal of an interatomic potential, in continuum units: what a
// law takes when its constants come from the MD potential (cubic_elastic's
// constants_from = "potential"). A coupling of two engines: the app supplies it
// (multiscale/), so that material/ knows nothing of MD.
struct Crystal {
  double density = 0.0, c11 = 0.0, c12 = 0.0, c44 = 0.0;
  std::string source;               // which crystal of which potential, for check and run.json
  std::vector<std::string> warnings;  // what the potential's file contradicts in the deck
};

// What a reader may need beyond its own table.
struct Context {
  int dim = 1;
  std::string deck_dir;   // files named in the table are relative to the deck
  std::string units;      // case.units ("" or a name of core/units)
  // The crystal of the potential that sub-table `key` of `table` describes (its problems
  // recorded against them; nullopt then). Empty where no MD engine is wired in.
  std::function<std::optional<Crystal>(Table& table, std::string_view key)> crystal_of;
  // Takes work a reader leaves until every key of the deck is read (md_closure's crystal
  // of its potential: many crystals built and relaxed), so that a deck's range errors come
  // at once, before it; the work gets the reader's table again to record its problems in.
  // Empty: the reader does the work at once.
  std::function<void(std::function<void(Table&)>)> later = {};
};

// The cost a law adds to every point beyond the continuum's own (md_closure: its MD box).
struct PointCost {
  double bytes = 0;          // held per point
  double scratch_bytes = 0;  // held per thread while the model steps
  double atoms = 0;          // atoms per point (0: no model inside the points)
  double steps_per_step = 0; // its steps per continuum step
  double setup_steps = 0;    // its steps before the first continuum step (relaxation)
  double prepare_atom_steps = 0;  // its work once before the points are built (Model::prepared)
  std::string size_key;      // the deck keys that size it
  // Its steps a second on one core, timed on this machine when the cost was asked for
  // (0: not measured; the budget then takes md::kMdAtomStepsPerSecond).
  double atom_steps_per_second = 0;
};

// Constants a reference or the run record reads off a law that has them.
struct IsotropicElastic {
  double E = 0, nu = 0;
};
struct GasLaw {
  double rho = 0, c = 0, gamma = 0;  // reference density, isothermal sound speed, adiabatic exponent
  bool isothermal = true;
};

// The parameters of one [material] table, read and checked.
class Model {
 public:
  virtual ~Model() = default;
  virtual std::string name() const = 0;
  // Density of unstrained material (elastic), or of the gas at its reference state.
  virtual double density() const = 0;
  // Solids take [initial.strain]; fluids take [initial.pressure].
  virtual bool solid() const = 0;
  // A point at initial strain e starts at density / (1 + e) (the multiscale cases).
  virtual bool density_of_unstrained() const { return false; }
  // Largest longitudinal wave speed of material at density rho and pressure p in `dim`
  // dimensions: the deck's CFL check and the 1-D references use it.
  virtual double wave_speed(int dim, double rho, double pressure) const = 0;
  // The gas law's density at pressure p (isothermal gas); NaN where not a function of p.
  virtual double density_at_pressure(double) const { return std::nan(""); }
  // Whether a [[body]] may take it as its own (md_closure is the deck's [material] only).
  virtual bool per_body() const { return true; }
  // Why a continuum step of dt does not suit the law ("" when it does).
  virtual std::string time_step_problem(double /*dt*/) const { return ""; }
  // The step every continuum step must be a whole number of (md_closure: its MD step, in
  // continuum units); 0 where any step does.
  virtual double time_quantum() const { return 0.0; }
  // The state a planar shock driven at particle speed `up` into the law at rest reaches:
  // its J = V / V0 and its fastest wave speed there (`mpmx check` sets a fixed dt against
  // it). Where the law has no Hugoniot of its own, J = 1 and the wave speed at rest.
  struct Shocked {
    double J = 1.0, wave_speed = 0.0;
    bool from_hugoniot = false;
  };
  virtual Shocked shocked(int dim, double /*up*/) const { return {1.0, wave_speed(dim, density(), 0.0), false}; }
  // What each point costs beyond the continuum's arrays, for a continuum step of dt
  // (md_closure times one of its boxes for it: not for the deck's reading).
  virtual PointCost point_cost(double /*dt*/) const { return {}; }
  // Atoms of the model inside each point (0: none), without timing anything.
  virtual double atoms_per_point() const { return 0; }
  // The law after the work a run does before its points are built (md_closure's NPT box,
  // prepare = "npt"), whose density the points take; nullptr when there is none. Reading
  // a deck leaves that work to the run: `check` states it (check_notes), `run` does it.
  virtual std::shared_ptr<const Model> prepared() const { return nullptr; }
  // A line to show before the points are built, when building them takes a while.
  virtual std::string build_note() const { return ""; }
  // What `mpmx check` says of the law beyond the deck's figures (none by default).
  virtual std::vector<std::string> check_notes() const { return {}; }
  // The constants the law runs with, by name with their units in the name, and where they
  // come from: run.json's materials[].constants and constants_from (none by default).
  virtual std::vector<std::pair<std::string, double>> constants() const { return {}; }
  virtual std::string constants_source() const { return ""; }
  // What the law is, for the code that needs its constants: linear isotropic elasticity,
  // an ideal gas, and the modulus of uniaxial strain a 1-D record names (0: none).
  virtual std::optional<IsotropicElastic> isotropic_elastic() const { return std::nullopt; }
  virtual std::optional<GasLaw> gas_law() const { return std::nullopt; }
  virtual double uniaxial_modulus() const { return 0.0; }
  virtual std::unique_ptr<Material<1>> make1() const = 0;
  virtual std::unique_ptr<Material<2>> make2() const = 0;
  virtual std::unique_ptr<Material<3>> make3() const = 0;
};

template <int Dim>
std::unique_ptr<Material<Dim>> make(const Model& m) {
  if constexpr (Dim == 1) return m.make1();
  else if constexpr (Dim == 2) return m.make2();
  else return m.make3();
}

}  // namespace mpmx::material
