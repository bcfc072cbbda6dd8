#pragma once
// run.json's "averages" of an NVT, NPT, NPH or Hugoniostat run: what a user quotes from
// it (the temperature, the pressure and each stress, the box and the lattice constant
// along each axis), each the mean over the thermo rows of the run's second half with its
// standard error from ten block means (the rows are correlated; blocks of a tenth of the
// window each are taken as independent), read back from thermo.csv, so that a resumed
// run averages the rows of the whole run as an uninterrupted one does.
#include <array>
#include <string>

#include <toml++/toml.h>

namespace mpmx::app::md {

// `thermo_csv`: the run's table; `first_step`: the first step of the window (rows from it
// on); `per_length`: lattice constant per box length along x, y, z (a / L).
toml::table ensemble_averages(const std::string& thermo_csv, std::int64_t first_step,
                              const std::array<double, 3>& per_length);

}  // namespace mpmx::app::md
