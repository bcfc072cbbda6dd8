#include "mpmx/mpm/state_checks.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/points.hpp"

namespace mpmx::mpm {

// A NaN or Inf anywhere stops the run naming the step, the particle and the field.
// The cheap per-step test is the sum of the new velocities and positions (from g2p)
// and the stress work of the step: any non-finite value poisons them.
template <int Dim>
void check_finite(const State<Dim>& s) {
  if (std::isfinite(s.finite_check) && std::isfinite(s.tallies.stress_work)) return;
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q) {
    if (!std::isfinite(p.volume[q]))
      throw RunError(fmt::format("non-finite volume ({}) at particle {} in step {} (t = {})", p.volume[q], q,
                                 s.step, s.time));
    for (int a = 0; a < Dim; ++a) {
      const std::pair<const char*, double> fields[] = {
          {"velocity", p.v[a][q]}, {"stress", p.stress[a * Dim + a][q]}, {"position", p.x[a][q]}};
      for (const auto& [name, v] : fields)
        if (!std::isfinite(v))  // the component by its axis: sigma_xx, the y velocity
          throw RunError(fmt::format("non-finite {} {} ({}) at particle {} in step {} (t = {})", name,
                                     std::string_view(&"xx\0yy\0zz"[3 * a], name[0] == 's' ? 2 : 1), v, q,
                                     s.step, s.time));
    }
  }
  throw RunError(fmt::format("non-finite stress work in step {} (t = {})", s.step, s.time));
}

// A particle whose volume is no longer positive has failed (tension or compression
// instability): checked where the volumes are read anyway, at the records.
template <int Dim>
void check_volumes(const State<Dim>& s) {
  const auto& p = s.particles;
  for (std::size_t q = 0; q < p.size(); ++q)
    if (!(p.volume[q] > 0.0))
      throw RunError(fmt::format("volume of particle {} fell to {} in step {} (t = {}): the "
                                 "material failed (tension or compression instability)",
                                 q, p.volume[q], s.step, s.time));
}

#define MPMX_STATE_CHECKS(D)                              \
  template void check_finite<D>(const State<D>&);         \
  template void check_volumes<D>(const State<D>&);
MPMX_STATE_CHECKS(1)
MPMX_STATE_CHECKS(2)
MPMX_STATE_CHECKS(3)
#undef MPMX_STATE_CHECKS

}  // namespace mpmx::mpm
