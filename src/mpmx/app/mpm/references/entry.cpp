// What every reference entry shares.
#include <cmath>

#include <fmt/format.h>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::app {

double Reference::total_energy(double) const { return std::nan(""); }
double Reference::signal_speed() const { return std::nan(""); }

void need(bool ok, std::string_view reference, std::string_view what) {
  if (!ok) throw InputError(fmt::format("reference '{}': {}", reference, what));
}

void ReferenceEntry::read_keys(Table& r, MpmConfig&, const std::string&) {
  if (r.has("file")) r.check(false, "file", "only reference direct_md reads a file");
}

}  // namespace mpmx::app
