#pragma once
// The analytic or exact solution a case is compared with, evaluated at a particle's
// position: the bridge between a deck's [reference] and mpmx::reference.
#include <memory>
#include <string>
#include <vector>

#include "mpmx/mpm/config.hpp"

namespace mpmx::mpm {

class Reference {
 public:
  virtual ~Reference() = default;
  // Fields it can give: a subset of velocity, strain, stress, pressure, density.
  virtual const std::vector<std::string>& fields() const = 0;
  virtual bool valid(double t) const = 0;
  virtual double value(const std::string& field, double x, double t) const = 0;
  // The undisturbed value of the field, the zero of the relative norms.
  virtual double baseline(const std::string& field) const = 0;
  // Total energy of the system where the reference knows it (NaN otherwise).
  virtual double total_energy(double t) const;
  // The fastest signal of the solution (2-D and 3-D decks compare only points that no
  // wall's reflection has reached); NaN where unbounded or unknown.
  virtual double signal_speed() const;
};

// nullptr when the deck names no field reference (none, or shock_front).
std::unique_ptr<Reference> make_reference(const MpmConfig& c);

// Value of a named field of particle q.
double particle_field(const Particles<1>& p, const std::string& field, std::size_t q);

}  // namespace mpmx::mpm
