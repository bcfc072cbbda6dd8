#pragma once
// An analytic or exact solution a case is compared with, evaluated at a position: what a
// reference entry (app/mpm/references.hpp) wraps around the solutions of reference/.
#include <string>
#include <vector>

namespace mpmx::app {

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

}  // namespace mpmx::app
