#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"
#include "mpmx/reference/riemann_isothermal.hpp"

namespace mpmx::app {

namespace {

class RiemannRef final : public Reference {
 public:
  explicit RiemannRef(reference::IsothermalRiemann r) : r_(r), star_(reference::solve_star(r)) {}
  const std::vector<std::string>& fields() const override { return fields_; }
  bool valid(double) const override { return true; }
  double value(const std::string& f, double x, double t) const override {
    const auto s = reference::sample(r_, star_, x, t);
    if (f == "velocity") return s.u;
    if (f == "pressure") return s.p;
    if (f == "stress") return -s.p;
    return s.rho;
  }
  double signal_speed() const override {
    return std::max({std::abs(star_.left.head), std::abs(star_.left.tail), std::abs(star_.right.head),
                     std::abs(star_.right.tail)});
  }
  // The undisturbed state ahead of the shock (the right state).
  double baseline(const std::string& f) const override {
    const double c2 = r_.c * r_.c;
    return f == "pressure" ? c2 * r_.right.rho
           : f == "stress" ? -c2 * r_.right.rho
           : f == "density" ? r_.right.rho
                            : r_.right.u;
  }

 private:
  reference::IsothermalRiemann r_;
  reference::IsothermalStar star_;
  std::vector<std::string> fields_{"velocity", "pressure", "stress", "density"};
};

}  // namespace

template <int Dim>
std::unique_ptr<Comparison<Dim>> RiemannIsothermalEntry::make(const MpmConfig& c) {
  need(c.pressure.kind == Profile::Kind::step, name, "needs [initial.pressure] profile = \"step\"");
  const double c_s = c.material.sound_speed, c2 = c_s * c_s;
  reference::IsothermalRiemann r;
  r.left = {c.pressure.left / c2, 0.0};
  r.right = {c.pressure.right / c2, 0.0};
  r.c = c_s;
  r.x0 = c.pressure.at;
  return std::make_unique<FieldComparison<Dim>>(c, std::make_unique<RiemannRef>(r), c.pressure);
}

template std::unique_ptr<Comparison<1>> RiemannIsothermalEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> RiemannIsothermalEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> RiemannIsothermalEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
