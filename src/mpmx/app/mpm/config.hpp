#pragma once
// A continuum run as read from its deck (app/mpm/deck.cpp does the reading and checks).
#include <array>
#include <cmath>
#include <memory>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/core/checked_count.hpp"
#include "mpmx/material/model.hpp"
#include "mpmx/mpm/bcs.hpp"
#include "mpmx/mpm/profile.hpp"
#include "mpmx/mpm/shape/scheme.hpp"

namespace mpmx::app {

// The most steps a continuum deck may take (time.end / time.dt): 1e15 is 30 years at a
// microsecond a step, and far inside what an int64 step counter and a double time hold.
inline constexpr double kMaxSteps = 1e15;

using mpm::Boundaries;
using mpm::Profile;
using mpm::SchemeOptions;

// The [material] table: the model read by its registry entry (material/registry.hpp),
// and for the 1-D references and messages the figures they read.
struct MaterialConfig {
  std::shared_ptr<const material::Model> spec;  // makes the run's Material<Dim>
  std::string model;             // spec->name()
  double density = 1.0;          // reference density (elastic: initial or unstrained density)
  bool density_unstrained = false;
  double youngs_modulus = 0.0;   // linear_elastic (md_closure: its crystal's C11)
  double sound_speed = 0.0;      // ideal_gas_isothermal: p = c^2 rho
  double gamma = 1.4;            // ideal_gas_adiabatic
  bool small_strain = false;     // force and work over V0 (geometrically linear, ADMPM's model)
  bool solid() const { return spec && spec->solid(); }
};

// A region of a 2-D or 3-D deck ([[body]]): it adds the grid's sub-cell points whose
// centres lie inside it (or removes them: a notch), with its own initial velocity.
struct Body {
  enum class Shape { box, circle, sphere, polygon };
  Shape shape = Shape::box;
  std::string name;                         // what a [[gauge]] calls it ("": none)
  bool remove = false;
  std::array<double, 3> lower{}, upper{};   // box; a polygon's bounding box
  std::array<double, 3> center{};           // circle, sphere
  double radius = 0.0;
  std::vector<std::array<double, 2>> vertices;  // polygon (2-D, x-y plane)
  std::array<double, 3> velocity{};
  double angular_velocity = 0.0;            // 2-D: a rigid spin about `center` (circle)
  std::shared_ptr<const material::Model> material;  // its own [body.material]; null: the deck's
  bool contains(const std::array<double, 3>& x, int dim) const;
};

// A [[gauge]]: the history of one material point (the nearest to `at` at the start,
// followed through the run), or of the outermost points of a body's face (their mean: a
// free-surface velocity, what a VISAR measures). Written every `every` steps to
// gauge_<name>.csv (app/mpm/gauges.hpp).
struct GaugeConfig {
  enum class Kind { point, free_surface };
  Kind kind = Kind::point;
  std::string name;
  std::array<double, 3> at{};  // point
  int body = -1;               // free_surface: the body's index (-1: every point of the deck)
  int face = 1;                // free_surface: x_lower, x_upper, y_lower, ... (mpm::face_name)
  std::int64_t every = 1;
};

struct ReferenceConfig {
  std::string name;              // "" = none
  std::string file;              // direct_md: the bar_stress.csv of an `mpmx md` bar run
  std::vector<std::string> fields;
  std::vector<double> times;     // times compared (also recorded)
  bool at_nodes = false;         // compare nodal (mapped) fields instead of particle fields
};

// [manufactured]: the axis-aligned manufactured solution of reference/manufactured.hpp
// (VALIDATION.md N4): its body force drives the run, its velocity starts it.
struct ManufacturedConfig {
  bool on = false;
  double amplitude = 0.01, speed = 1.0;
};

struct MpmConfig {
  // [case]
  std::string id, title, seed, units;
  // [grid] (lower, upper, cells: the x axis, as 1-D decks give them; the arrays: every axis)
  int dim = 1;
  double lower = 0.0, upper = 1.0;
  int cells = 1;
  std::array<double, 3> lower_all{}, upper_all{1.0, 1.0, 1.0};
  std::array<int, 3> cells_all{1, 1, 1};
  // [particles]
  int per_cell = 2;                       // along x
  std::array<int, 3> per_cell_all{2, 1, 1};
  bool move = true;
  // [[body]] (2-D, 3-D); none: the whole grid is filled
  std::vector<Body> bodies;
  // [scheme]
  SchemeOptions scheme;
  // [material]
  MaterialConfig material;
  // [initial]: velocity always; strain (solids) or pressure (gases)
  Profile velocity, strain, pressure;
  // [boundary]
  Boundaries boundary;
  // [viscosity] linear artificial viscosity coefficient (0 = off), ch. 6; tensor form
  double viscosity = 0.0;
  bool tensor_viscosity = false;
  double c_L = 1.5, c_q = 2.0;
  // [mass_distribution] eqs. 7.4-7.7: on by default for DDMP in 2-D and 3-D
  bool mass_distribution = false;
  double mass_fraction = 0.04;       // m_eps as a fraction of the mean point mass
  // [time] (dt = "cfl": each step's from the state, cfl x dx_min / max (c + |v|); dt then
  // holds the first step's, for estimates)
  double dt = 0.0, end = 0.0;
  bool cfl_dt = false;
  double cfl = 0.5;
  // dt = "cfl": the most any point's volume may change in one step (|tr L| dt, L the last
  // step's velocity gradient; mpm/step_limit.hpp)
  double max_volume_strain = 0.1;
  double cfl_limit = 1.0;  // a number dt: the largest Courant number its initial state may take
  // [time] energy_growth: the growth of the total energy (kinetic + stored, less the
  // boundary's work) over the initial scale that ends a run with status "energy_growth"
  // and a warning; energy_growth_stop: the growth that stops it at once (laws that keep
  // an energy account only).
  double energy_growth = 0.1, energy_growth_stop = 1.0;
  // [output]
  std::vector<double> output_times;
  std::int64_t output_every = 0;   // 0 = only output_times and the last step
  bool write_nodes = true, write_particles = true, plot = true;
  bool write_vtk = true;             // 2-D, 3-D: VTK files for ParaView
  // xt_sigma_xx.csv (app/mpm/xt_diagram.hpp) every xt_every steps (0: about 400 rows over
  // the run): on by default where the deck has a piston or a gauge and is 1-D or
  // quasi-1-D (every axis but x at most 8 cells)
  bool write_xt = false;
  std::int64_t xt_every = 0;
  // [[gauge]]
  std::vector<GaugeConfig> gauges;
  // md_dump: the points whose MD boxes are written as LAMMPS dumps, every so many steps
  // (0: at the records)
  std::vector<std::int64_t> md_dump_points;
  std::int64_t md_dump_every = 0;
  std::vector<std::string> md_dump_fields;  // per-atom columns (md/lammps_dump.hpp)
  // [reference]
  ReferenceConfig reference;
  ManufacturedConfig manufactured;
  // [convergence] levels: the run repeated on grids refined by 2 (dt with them), the
  // observed order of each compared field fitted over the levels (mpm/convergence.hpp)
  int convergence_levels = 1;

  toml::table deck;                // the deck as written, echoed into run.json
  std::string deck_path;

  // end / dt (with dt = "cfl", the first step's dt): the deck refuses more than kMaxSteps,
  // so that the count never wraps.
  std::int64_t steps() const { return rounded_count(end / dt).value_or(std::numeric_limits<std::int64_t>::max()); }
  double dx() const { return (upper - lower) / cells; }
};

}  // namespace mpmx::app
