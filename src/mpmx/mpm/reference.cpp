#include "mpmx/mpm/reference.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/reference/bar_history.hpp"
#include "mpmx/reference/gas_wave.hpp"
#include "mpmx/reference/riemann_isothermal.hpp"
#include "mpmx/reference/standing_wave.hpp"
#include "mpmx/reference/wave_reflection.hpp"

namespace mpmx::mpm {

double Reference::total_energy(double) const { return std::nan(""); }
double Reference::signal_speed() const { return std::nan(""); }

double particle_field(const Particles<1>& p, const std::string& f, std::size_t q) {
  if (f == "velocity") return p.v[0][q];
  if (f == "strain") return p.strain[0][q];
  if (f == "stress") return p.stress[0][q];
  if (f == "pressure") return -p.stress[0][q];
  if (f == "density") return p.density(q);
  throw InputError("unknown field '" + f + "'");
}

namespace {

// Wraps a solution of the elastic bar (standing wave, wave reflection).
template <class Solution>
class ElasticBar final : public Reference {
 public:
  ElasticBar(Solution w, double t_end) : w_(w), t_end_(t_end) {}
  const std::vector<std::string>& fields() const override { return fields_; }
  bool valid(double t) const override { return t <= t_end_ * (1 + 1e-12); }
  double value(const std::string& f, double x, double t) const override {
    if (f == "velocity") return reference::velocity(w_, x, t);
    if (f == "strain") return reference::strain(w_, x, t);
    if (f == "stress") return reference::stress(w_, x, t);
    return reference::density(w_, x, t);
  }
  double baseline(const std::string& f) const override { return f == "density" ? w_.rho0 : 0.0; }
  double total_energy(double t) const override {
    if constexpr (std::is_same_v<Solution, reference::WaveReflection>)
      return valid(t) ? reference::total_energy(w_, t) : std::nan("");
    return std::nan("");
  }

 private:
  Solution w_;
  double t_end_;
  std::vector<std::string> fields_{"velocity", "strain", "stress", "density"};
};

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

class RiemannRef final : public Reference {
 public:
  explicit RiemannRef(reference::IsothermalRiemann r)
      : r_(r), star_(reference::solve_star(r)) {}
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

// A direct-MD bar's binned stress: the bar between its walls maps onto the grid
// [lower, upper], its times (ps) and stresses (GPa) onto the deck's units.
class DirectMd final : public Reference {
 public:
  DirectMd(reference::BarHistory h, double lower, double length, units::UnitSystem u)
      : h_(std::move(h)), lower_(lower), length_(length), u_(u) {}
  const std::vector<std::string>& fields() const override { return fields_; }
  bool valid(double t) const override { return h_.has(t * u_.time_ps); }
  double value(const std::string& f, double x, double t) const override {
    const double s = h_.sxx(t * u_.time_ps, (x - lower_) / length_) / u_.stress_GPa;
    return f == "pressure" ? -s : s;
  }
  double baseline(const std::string&) const override { return 0.0; }

 private:
  reference::BarHistory h_;
  double lower_, length_;
  units::UnitSystem u_;
  std::vector<std::string> fields_{"stress", "pressure"};
};

}  // namespace

std::unique_ptr<Reference> make_reference(const MpmConfig& c) {
  const auto& name = c.reference.name;
  const double L = c.upper - c.lower;
  const auto& m = c.material;
  auto need = [&](bool ok, const char* what) {
    if (!ok) throw InputError("reference '" + name + "': " + what);
  };
  if (name == "direct_md" && c.dim > 1) return nullptr;  // the jet's maps (mpm/run.cpp)
  if (name == "direct_md") {
    const auto u = units::unit_system(c.units);
    need(u.has_value(), "needs case.units to name a unit system");
    auto history = reference::BarHistory::read(c.reference.file);
    for (double t : c.reference.times)  // a compared time missing from the table is an error, not a skip
      need(history.has(t * u->time_ps),
           fmt::format("{} has no record at t = {} ({} ps); its last is at {} ps", c.reference.file, t,
                       t * u->time_ps, history.last_time_ps())
               .c_str());
    return std::make_unique<DirectMd>(std::move(history), c.lower, L, *u);
  }
  if (name == "standing_wave") {
    need(m.model == "linear_elastic", "needs material.model = \"linear_elastic\"");
    need(c.velocity.kind == Profile::Kind::sinusoid, "needs [initial.velocity] profile = \"sinusoid\"");
    reference::StandingWave w;
    w.L = L;
    w.c = std::sqrt(m.youngs_modulus / m.density);
    w.v0 = c.velocity.amplitude;
    w.n = static_cast<int>(c.velocity.mode);
    w.rho0 = m.density;
    return std::make_unique<ElasticBar<reference::StandingWave>>(w, c.end);
  }
  if (name == "wave_reflection") {
    need(m.model == "linear_elastic", "needs material.model = \"linear_elastic\"");
    need(c.boundary.right().type == BoundarySide::Type::velocity, "needs a velocity drive on the right");
    reference::WaveReflection w;
    w.L = L;
    w.c = std::sqrt(m.youngs_modulus / m.density);
    w.v0 = c.boundary.right().amplitude[0];
    w.omega = c.boundary.right().omega;
    w.rho0 = m.density;
    return std::make_unique<ElasticBar<reference::WaveReflection>>(w, reference::end_time(w));
  }
  if (name == "gas_wave") {
    need(m.model == "ideal_gas_adiabatic", "needs material.model = \"ideal_gas_adiabatic\"");
    need(c.boundary.right().type == BoundarySide::Type::velocity, "needs a velocity drive on the right");
    reference::GasWave g;
    g.L = L;
    g.gamma = m.gamma;
    g.p0 = c.pressure.value;
    g.rho0 = m.density;
    g.v0 = c.boundary.right().amplitude[0];
    g.omega = c.boundary.right().omega;
    return std::make_unique<GasWaveRef>(g);
  }
  if (name == "riemann_isothermal") {
    need(m.model == "ideal_gas_isothermal", "needs material.model = \"ideal_gas_isothermal\"");
    need(c.pressure.kind == Profile::Kind::step, "needs [initial.pressure] profile = \"step\"");
    reference::IsothermalRiemann r;
    const double c2 = m.sound_speed * m.sound_speed;
    r.left = {c.pressure.left / c2, 0.0};
    r.right = {c.pressure.right / c2, 0.0};
    r.c = m.sound_speed;
    r.x0 = c.pressure.at;
    return std::make_unique<RiemannRef>(r);
  }
  return nullptr;
}

}  // namespace mpmx::mpm
