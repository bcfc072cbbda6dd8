#include "mpmx/app/mpm/preflight.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "mpmx/app/mpm/bodies.hpp"
#include "mpmx/app/mpm/comparison.hpp"
#include "mpmx/core/error.hpp"

namespace mpmx::app {

MpmPreflight preflight_mpm(const MpmConfig& c, int ranks, std::uint64_t memory_bytes, bool force) {
  MpmPreflight p;
  // The estimate first: it bounds what placing the bodies' points costs.
  p.budget = estimate_mpm(c, ranks);
  check_mpm_budget(p.budget, memory_bytes, force);
  check_bodies(c);
  std::error_code ec;
  if (!c.reference.file.empty() && !std::filesystem::exists(c.reference.file, ec)) {
    p.pending = fmt::format("reference.file {} is not there yet: `mpmx run` needs it (run its direct-MD deck first)",
                            c.reference.file);
  } else if (c.dim == 1) {
    (void)make_comparison<1>(c);
  } else if (c.dim == 2) {
    (void)make_comparison<2>(c);
  } else {
    (void)make_comparison<3>(c);
  }
  return p;
}

MpmPreflight preflight_mpm_run(const MpmConfig& c, int ranks, std::uint64_t memory_bytes, bool force) {
  MpmPreflight p = preflight_mpm(c, ranks, memory_bytes, force);
  if (!p.pending.empty()) throw InputError(p.pending);
  return p;
}

}  // namespace mpmx::app
