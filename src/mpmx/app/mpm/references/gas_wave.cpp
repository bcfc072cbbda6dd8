#include <string>
#include <vector>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"
#include "mpmx/reference/gas_wave.hpp"

namespace mpmx::app {

namespace {

class GasWaveRef final : public Reference {
 public:
  explicit GasWaveRef(reference::GasWave g) : g_(g) {}
  const std::vector<std::string>& fields() const override { return fields_; }
  bool valid(double t) const override { return t <= reference::end_time(g_); }
  double value(const std::string& f, double x, double t) const override {
    if (f == "velocity") return reference::velocity(g_, x, t);
    if (f == "pressure") return reference::pressure(g_, x, t);
    if (f == "stress") return -reference::pressure(g_, x, t);
    return reference::density(g_, x, t);
  }
  double baseline(const std::string& f) const override {
    return f == "pressure" ? g_.p0 : f == "stress" ? -g_.p0 : f == "density" ? g_.rho0 : 0.0;
  }

 private:
  reference::GasWave g_;
  std::vector<std::string> fields_{"velocity", "pressure", "stress", "density"};
};

}  // namespace

template <int Dim>
std::unique_ptr<Comparison<Dim>> GasWaveEntry::make(const MpmConfig& c) {
  if constexpr (Dim != 1) {
    return nullptr;
  } else {
    need(c.boundary.right().type == mpm::BoundarySide::Type::velocity, name, "needs a velocity drive on the right");
    reference::GasWave g;
    g.L = c.upper - c.lower;
    g.gamma = c.material.gamma;
    g.p0 = c.pressure.value;
    g.rho0 = c.material.density;
    g.v0 = c.boundary.right().amplitude[0];
    g.omega = c.boundary.right().omega;
    return std::make_unique<FieldComparison<1>>(c, std::make_unique<GasWaveRef>(g), c.velocity);
  }
}

template std::unique_ptr<Comparison<1>> GasWaveEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> GasWaveEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> GasWaveEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
