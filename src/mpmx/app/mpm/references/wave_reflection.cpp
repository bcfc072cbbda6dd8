#include <cmath>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"

namespace mpmx::app {

template <int Dim>
std::unique_ptr<Comparison<Dim>> WaveReflectionEntry::make(const MpmConfig& c) {
  if constexpr (Dim != 1) {
    return nullptr;
  } else {
    need(c.boundary.right().type == mpm::BoundarySide::Type::velocity, name, "needs a velocity drive on the right");
    const auto& m = c.material;
    reference::WaveReflection w;
    w.L = c.upper - c.lower;
    w.c = std::sqrt(m.youngs_modulus / m.density);
    w.v0 = c.boundary.right().amplitude[0];
    w.omega = c.boundary.right().omega;
    w.rho0 = m.density;
    return std::make_unique<FieldComparison<1>>(
        c, std::make_unique<ElasticBar<reference::WaveReflection>>(w, reference::end_time(w)), c.velocity);
  }
}

template std::unique_ptr<Comparison<1>> WaveReflectionEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> WaveReflectionEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> WaveReflectionEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
