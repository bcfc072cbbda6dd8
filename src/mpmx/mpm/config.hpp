#pragma once
// A continuum run as read from its deck (io/mpm_deck.cpp does the reading and checks).
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/material/md_closure.hpp"
#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/profile.hpp"
#include "mpmx/mpm/shape/scheme.hpp"

namespace mpmx::mpm {

struct MaterialConfig {
  std::string model;             // linear_elastic | ideal_gas_isothermal | ideal_gas_adiabatic | md_closure
  double density = 1.0;          // reference density (elastic: initial density)
  // Solids: `density` is that of the unstrained material, so a point at initial strain
  // e starts at density / (1 + e) (the multiscale cases); else every point starts at it.
  bool density_unstrained = false;
  double youngs_modulus = 0.0;   // linear_elastic
  double poisson_ratio = 0.0;    // linear_elastic, 2-D/3-D only
  bool small_strain = false;     // force and work over V0 (geometrically linear, ADMPM's model)
  double sound_speed = 0.0;      // ideal_gas_isothermal: p = c^2 rho
  double gamma = 1.4;            // ideal_gas_adiabatic
  material::MdClosureConfig md;  // md_closure (density and youngs_modulus hold its crystal's)
  bool solid() const { return model == "linear_elastic" || model == "md_closure"; }
};

struct ReferenceConfig {
  std::string name;              // "" = none
  std::string file;              // direct_md: the bar_stress.csv of an `mpmx md` bar run
  std::vector<std::string> fields;
  std::vector<double> times;     // times compared (also recorded)
  bool at_nodes = false;         // compare nodal (mapped) fields instead of particle fields
};

struct MpmConfig {
  // [case]
  std::string id, title, seed, units;
  // [grid]
  int dim = 1;
  double lower = 0.0, upper = 1.0;
  int cells = 1;
  // [particles]
  int per_cell = 2;
  bool move = true;
  // [scheme]
  SchemeOptions scheme;
  // [material]
  MaterialConfig material;
  // [initial]: velocity always; strain (solids) or pressure (gases)
  Profile velocity, strain, pressure;
  // [boundary]
  Boundaries boundary;
  // [viscosity] linear artificial viscosity coefficient (0 = off), ch. 6
  double viscosity = 0.0;
  // [time]
  double dt = 0.0, end = 0.0;
  // [output]
  std::vector<double> output_times;
  std::int64_t output_every = 0;   // 0 = only output_times and the last step
  bool write_nodes = true, write_particles = true, plot = true;
  // [reference]
  ReferenceConfig reference;

  toml::table deck;                // the deck as written, echoed into run.json
  std::string deck_path;

  std::int64_t steps() const { return static_cast<std::int64_t>(std::llround(end / dt)); }
  double dx() const { return (upper - lower) / cells; }
};

}  // namespace mpmx::mpm
