#pragma once
// What advances the particles between two force evaluations when it is not the system's
// own velocity Verlet: given the pair forces at the current positions (p.fx, p.fy, p.fz,
// eV/Angstrom), a mover sets the velocities and positions of every particle (mobile,
// rigid and external) one step dt later. The DPD/MPM-grid model (seed 004 sec. 3.2,
// steps s1-s14) is one: its grid lives in multiscale/, so dpd/ knows only this.
#include <functional>
#include <iosfwd>
#include <memory>

#include <toml++/toml.h>

#include "mpmx/dpd/particles.hpp"

namespace mpmx::dpd {

class Mover {
 public:
  virtual ~Mover() = default;
  virtual void move(Particles& p, double dt) = 0;
  // What run.json records of the model (its name, grid, counters).
  virtual void report(toml::table& out) const = 0;
  // Checkpoint: the mover's own state (its grid's place, a continuum's points), so a
  // resumed run continues bit-for-bit; load() replaces the state of a mover made by the
  // same deck's factory (InputError for one that does not fit).
  virtual void save(std::ostream& out) const = 0;
  virtual void load(std::istream& in) = 0;
};

class System;

// Makes the mover of a run (the DPD/MPM grid) from the system at the run's start, after
// the equilibration and the continuum's points are marked; empty: the system's own
// velocity Verlet.
using MoverFactory = std::function<std::unique_ptr<Mover>(System&)>;

}  // namespace mpmx::dpd
