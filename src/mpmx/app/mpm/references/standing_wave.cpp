#include <cmath>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"

namespace mpmx::app {

template <int Dim>
std::unique_ptr<Comparison<Dim>> StandingWaveEntry::make(const MpmConfig& c) {
  if constexpr (Dim != 1) {
    return nullptr;
  } else {
    need(c.velocity.kind == Profile::Kind::sinusoid, name, "needs [initial.velocity] profile = \"sinusoid\"");
    const auto& m = c.material;
    reference::StandingWave w;
    w.L = c.upper - c.lower;
    w.c = std::sqrt(m.youngs_modulus / m.density);
    w.v0 = c.velocity.amplitude;
    w.n = static_cast<int>(c.velocity.mode);
    w.rho0 = m.density;
    return std::make_unique<FieldComparison<1>>(c, std::make_unique<ElasticBar<reference::StandingWave>>(w, c.end),
                                                c.velocity);
  }
}

template std::unique_ptr<Comparison<1>> StandingWaveEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> StandingWaveEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> StandingWaveEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
