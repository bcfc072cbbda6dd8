#include "mpmx/app/mpm/comparison.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/app/mpm/references.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/mpm/nodal_fields.hpp"

namespace mpmx::app {

using namespace mpm;

void ErrorBook::add(const std::string& f, const reference::ErrorNorms& n, double peak, double t) {
  auto& e = errors[f];
  e.l1 = std::max(e.l1, n.l1);
  e.l2 = std::max(e.l2, n.l2);
  e.peak = std::max(e.peak, peak);
  toml::table at;
  at.insert("time", t);
  at.insert("l1", n.l1);
  at.insert("l2", n.l2);
  at.insert("peak", peak);
  rec_->append(fmt::format("errors.{}.by_time", f), std::move(at));
}

void ErrorBook::add_samples(const std::string& f, const std::vector<double>& u, const std::vector<double>& uref,
                            const std::vector<double>& w, double baseline, double t,
                            const reference::ErrorScale& scale) {
  if (u.empty()) return;
  const auto n = reference::scaled_error_norms(u, uref, w, baseline, scale);
  double dmax = 0.0, rmax = scale.peak;
  for (std::size_t k = 0; k < u.size(); ++k) {
    dmax = std::max(dmax, std::abs(u[k] - uref[k]));
    rmax = std::max(rmax, std::abs(uref[k] - baseline));
  }
  add(f, n, rmax > 0.0 ? dmax / rmax : 0.0, t);
}

void ErrorBook::add_eq712(const reference::Eq712& now, double t) {
  toml::table at;
  at.insert("time", t);
  at.insert("error", now.value());
  rec_->append("errors_by_time.stress_vs_direct_md", std::move(at));
}

double particle_field(const Particles<1>& p, const std::string& f, std::size_t q) {
  if (f == "velocity") return p.v[0][q];
  if (f == "strain") return p.strain[0][q];
  if (f == "stress") return p.stress[0][q];
  if (f == "pressure") return -p.stress[0][q];
  if (f == "density") return p.density(q);
  throw InputError("unknown field '" + f + "'");
}

template <int Dim>
FieldComparison<Dim>::FieldComparison(const MpmConfig& c, std::unique_ptr<Reference> ref, const Profile& along,
                                      bool pool_eq712)
    : c_(c), ref_(std::move(ref)), along_(along), pool_eq712_(pool_eq712) {}

template <int Dim>
const reference::ErrorScale& FieldComparison<Dim>::scale(const std::string& f) {
  // Once per field: the solution at every compared time on evenly spaced samples along
  // the grid (along the profile's normal in 2-D/3-D), not the run's points, so that a
  // resumed run measures with the same scale.
  auto [it, fresh] = scale_.try_emplace(f);
  if (!fresh) return it->second;
  double lo = 0.0, hi = 0.0;
  for (int d = 0; d < Dim; ++d) {
    const double n = Dim == 1 ? 1.0 : along_.normal[d];
    const double a = n * c_.lower_all[d], b = n * c_.upper_all[d];
    lo += std::min(a, b), hi += std::max(a, b);
  }
  constexpr std::size_t kSamples = 4096;
  std::vector<double> r(kSamples), w(kSamples, 1.0);
  for (double t : c_.reference.times) {
    if (!ref_->valid(t)) continue;
    for (std::size_t k = 0; k < kSamples; ++k) r[k] = ref_->value(f, lo + (hi - lo) * (k + 0.5) / kSamples, t);
    const reference::ErrorScale now = reference::disturbance(r, w, ref_->baseline(f));
    it->second.mean_abs = std::max(it->second.mean_abs, now.mean_abs);
    it->second.rms = std::max(it->second.rms, now.rms);
    it->second.peak = std::max(it->second.peak, now.peak);
  }
  return it->second;
}

template <int Dim>
void FieldComparison<Dim>::compare(const State<Dim>& s, ErrorBook& book) {
  if (!ref_->valid(s.time)) return;
  if constexpr (Dim == 1) compare_1d(s, book);
  else compare_along_normal(s, book);
}

template <int Dim>
void FieldComparison<Dim>::compare_1d(const State<Dim>& s, ErrorBook& book) {
  if constexpr (Dim == 1) {
    const auto& p = s.particles;
    if (pool_eq712_) {  // eq. 7.12: every point against the direct-MD bin it lies in
      reference::Eq712 now;
      for (std::size_t q = 0; q < p.size(); ++q) {
        const double md = ref_->value("stress", p.x[0][q], s.time);
        now.add(p.stress[0][q], md);
        book.eq712.add(p.stress[0][q], md);
      }
      book.add_eq712(now, s.time);
    }
    const NodalFields nf = c_.reference.at_nodes ? nodal_fields(s) : NodalFields{};
    for (const auto& f : c_.reference.fields) {
      u_.clear(), uref_.clear(), w_.clear();
      if (c_.reference.at_nodes) {
        for (std::size_t i = 0; i < nf.size(); ++i) {
          if (nf.mass[i] <= 0.0) continue;
          u_.push_back(nf.field(f, i));
          uref_.push_back(ref_->value(f, nf.x[i], s.time));
          w_.push_back(nf.volume[i]);
        }
      } else {
        for (std::size_t q = 0; q < p.size(); ++q) {
          u_.push_back(particle_field(p, f, q));
          uref_.push_back(ref_->value(f, p.x[0][q], s.time));
          w_.push_back(p.volume[q]);
        }
      }
      book.add_samples(f, u_, uref_, w_, ref_->baseline(f), s.time, scale(f));
    }
  }
}

template <int Dim>
void FieldComparison<Dim>::compare_along_normal(const State<Dim>& s, ErrorBook& book) {
  const auto& p = s.particles;
  // Along the normal of the initial profile, over the points no wall has signalled to
  // yet: farther than (fastest signal) t + 2 cells from every face.
  const Profile& prof = along_;
  double dx_max = 0.0;
  for (int d = 0; d < Dim; ++d) dx_max = std::max(dx_max, s.grid.dx[d]);
  const double speed = ref_->signal_speed();
  const double margin = (std::isfinite(speed) ? speed * s.time : 0.0) + 2.0 * dx_max;
  for (const auto& f : c_.reference.fields) {
    u_.clear(), uref_.clear(), w_.clear();
    for (std::size_t q = 0; q < p.size(); ++q) {
      std::array<double, 3> x{};
      bool inside = true;
      for (int d = 0; d < Dim; ++d) {
        x[d] = p.x[d][q];
        inside = inside && x[d] - s.grid.lower[d] > margin && s.grid.upper[d] - x[d] > margin;
      }
      if (!inside) continue;
      double value = 0.0, vn = 0.0, snn = 0.0, tr = 0.0;
      for (int a = 0; a < Dim; ++a) {
        vn += p.v[a][q] * prof.normal[a];
        tr += p.stress[a * Dim + a][q];
        for (int b = 0; b < Dim; ++b) snn += prof.normal[a] * p.stress[a * Dim + b][q] * prof.normal[b];
      }
      if (f == "velocity") value = vn;
      else if (f == "pressure") value = -tr / Dim;
      else if (f == "stress") value = snn;
      else if (f == "density") value = p.mass[q] / p.volume[q];
      else value = p.strain[0][q];
      u_.push_back(value);
      uref_.push_back(ref_->value(f, prof.along(x, Dim), s.time));
      w_.push_back(p.volume[q]);
    }
    book.add_samples(f, u_, uref_, w_, ref_->baseline(f), s.time, scale(f));
  }
}

template <int Dim>
std::unique_ptr<Comparison<Dim>> make_comparison(const MpmConfig& c) {
  if (c.reference.name.empty()) return nullptr;
  return References::with(
      c.reference.name,
      [&]<class E>() -> std::unique_ptr<Comparison<Dim>> {
        if (!E::material.empty() && c.material.model != E::material)
          throw InputError(fmt::format("reference '{}': needs material.model = \"{}\"", E::name, E::material));
        if (!(E::dims >> (Dim - 1) & 1u)) return nullptr;  // the deck reader refused it
        return E::template make<Dim>(c);
      },
      [] { return std::unique_ptr<Comparison<Dim>>(); });
}

std::vector<std::string> reference_names(int dim) {
  std::vector<std::string> names;
  References::each([&]<class E>() {
    if (E::dims >> (dim - 1) & 1u) names.emplace_back(E::name);
  });
  return names;
}

template class FieldComparison<1>;
template class FieldComparison<2>;
template class FieldComparison<3>;
template std::unique_ptr<Comparison<1>> make_comparison<1>(const MpmConfig&);
template std::unique_ptr<Comparison<2>> make_comparison<2>(const MpmConfig&);
template std::unique_ptr<Comparison<3>> make_comparison<3>(const MpmConfig&);

}  // namespace mpmx::app
