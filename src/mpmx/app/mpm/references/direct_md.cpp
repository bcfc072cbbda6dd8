#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/app/mpm/references/elastic_bar.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/reference/bar_history.hpp"
#include "mpmx/reference/jet_history.hpp"

namespace mpmx::app {

namespace {

// A direct-MD bar's binned stress: the bar between its walls maps onto the grid
// [lower, upper], its times (ps) and stresses (GPa) onto the deck's units.
class BarStress final : public Reference {
 public:
  BarStress(reference::BarHistory h, double lower, double length, units::UnitSystem u)
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

// Eq. 7.12 on sigma_xx, each point against the jet's bin it lies in (2-D, 3-D); the
// continuum's x = 0 is the piston's face.
template <int Dim>
class JetComparison final : public Comparison<Dim> {
 public:
  JetComparison(reference::JetHistory jet, units::UnitSystem u) : jet_(std::move(jet)), u_(u) {}
  void compare(const mpm::State<Dim>& s, ErrorBook& book) override {
    const auto& p = s.particles;
    reference::Eq712 now;
    const double t_ps = s.time * u_.time_ps, L = u_.length_A;
    for (std::size_t q = 0; q < p.size(); ++q) {
      const double md = jet_.sxx(t_ps, jet_.piston_face_A() + L * p.x[0][q], L * p.x[1][q]);
      if (!std::isfinite(md)) continue;  // outside the bins, or an empty bin
      now.add(p.stress[0][q], md / u_.stress_GPa);
      book.eq712.add(p.stress[0][q], md / u_.stress_GPa);
    }
    book.add_eq712(now, s.time);
  }

 private:
  reference::JetHistory jet_;
  units::UnitSystem u_;
};

}  // namespace

void DirectMdEntry::read_keys(Table& r, MpmConfig& c, const std::string& deck_dir) {
  const std::filesystem::path f = r.string("file");
  c.reference.file = f.is_absolute() || deck_dir.empty() ? f.string() : (deck_dir / f).string();
  r.check(units::unit_system(c.units).has_value(), "name",
          fmt::format("direct_md needs case.units to be one of {} (the MD side is in Angstrom, ps, GPa)",
                      units::unit_system_names()));
  if (c.reference.fields.empty() && c.dim == 1) c.reference.fields = {"stress"};
  if (c.dim > 1 && !c.reference.fields.empty())
    r.check(false, "fields", "a 2-D or 3-D direct_md comparison is eq. 7.12 on sigma_xx; it takes no fields");
  if (c.dim > 1) r.check(!c.reference.times.empty(), "times", "direct_md compares at the times listed here");
}

template <int Dim>
std::unique_ptr<Comparison<Dim>> DirectMdEntry::make(const MpmConfig& c) {
  if constexpr (Dim > 1) {
    auto jet = reference::JetHistory::read(c.reference.file);
    const auto u = units::unit_system(c.units);
    for (double t : c.reference.times)
      if (!jet.has(t * u->time_ps))
        throw InputError(fmt::format("{} has no record at t = {} ({} ps); its last is at {} ps", c.reference.file, t,
                                     t * u->time_ps, jet.last_time_ps()));
    return std::make_unique<JetComparison<Dim>>(std::move(jet), *u);
  } else {
    const auto u = units::unit_system(c.units);
    need(u.has_value(), name, "needs case.units to name a unit system");
    auto history = reference::BarHistory::read(c.reference.file);
    for (double t : c.reference.times)  // a compared time missing from the table is an error, not a skip
      need(history.has(t * u->time_ps), name,
           fmt::format("{} has no record at t = {} ({} ps); its last is at {} ps", c.reference.file, t,
                       t * u->time_ps, history.last_time_ps()));
    return std::make_unique<FieldComparison<1>>(
        c, std::make_unique<BarStress>(std::move(history), c.lower, c.upper - c.lower, *u), c.velocity, true);
  }
}

template std::unique_ptr<Comparison<1>> DirectMdEntry::make<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> DirectMdEntry::make<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> DirectMdEntry::make<3>(const MpmConfig&);

}  // namespace mpmx::app
