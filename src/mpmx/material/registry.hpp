#pragma once
// Materials by name. A [material] table is read by its model's own reader into a
// dimension-free Model (the parameters, checked), which then makes the Material of the
// run's dimension. Adding a material touches its own file and one line of registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mpmx/io/deck.hpp"
#include "mpmx/material/material.hpp"

namespace mpmx::material {

// What a reader may need beyond its own table.
struct Context {
  int dim = 1;
  std::string deck_dir;   // files named in the table are relative to the deck
  std::string units;      // case.units ("" or a name of core/units)
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

// One registry entry: the model's name and its table reader. A reader records every
// problem in its Section (key, value, reason) and returns a usable model anyway.
struct Entry {
  std::string name;
  std::function<std::shared_ptr<const Model>(io::Section&, const Context&)> read;
};
const std::vector<Entry>& registry();
std::vector<std::string> names();

// Reads `model` and dispatches to its reader; an unknown name is an error listing them.
std::shared_ptr<const Model> read(io::Section& table, const Context& ctx);

}  // namespace mpmx::material
