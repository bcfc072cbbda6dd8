#include "mpmx/material/cubic_elastic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/core/binary.hpp"

namespace mpmx::material {

double CubicConstants::wave_modulus(int dim) const {
  if (dim == 1) return c11;
  double m = std::max({c11, c44, 0.5 * (c11 + c12 + 2.0 * c44), 0.5 * (c11 - c12)});
  if (dim == 3) m = std::max({m, (c11 + 2.0 * c12 + 4.0 * c44) / 3.0, (c11 - c12 + c44) / 3.0});
  return m;
}

template <int Dim>
typename CubicElastic<Dim>::Mat CubicElastic<Dim>::axes(std::size_t q) const {
  if constexpr (Dim == 1) {
    (void)q;
    return Mat::Identity();
  } else {
    return Eigen::Map<const Eigen::Matrix<double, Dim, Dim, Eigen::RowMajor>>(&axes_[q * Dim * Dim]);
  }
}

template <int Dim>
void CubicElastic<Dim>::set_stress(const Points<Dim>& p, std::size_t q) const {
  if constexpr (Dim == 1) {
    p.stress[0][q] = c_.c11 * p.strain[0][q];
  } else {
    const Mat Q = axes(q);
    const Mat eps = jaumann::gather<Dim>(p.strain, q);
    const Mat s = Q * c_.stress<Dim>(Q.transpose() * eps * Q) * Q.transpose();
    jaumann::scatter<Dim>(0.5 * (s + s.transpose()), q, p.stress);
    if constexpr (Dim == 2) p.set_sigma_zz(q, out_of_plane_stress(p, q));
  }
}

template <int Dim>
void CubicElastic<Dim>::initialize(const Points<Dim>& p) {
  if constexpr (Dim > 1) {
    axes_.assign(p.size() * Dim * Dim, 0.0);
    for (std::size_t q = 0; q < p.size(); ++q)
      for (int a = 0; a < Dim; ++a) axes_[q * Dim * Dim + a * Dim + a] = 1.0;
  }
  for (std::size_t q = 0; q < p.size(); ++q) set_stress(p, q);
}

template <int Dim>
void CubicElastic<Dim>::update_stress(const Points<Dim>& p, double dt) {
  if constexpr (Dim == 1) {
    double* __restrict eps = p.strain[0];
    double* __restrict sig = p.stress[0];
    const double* __restrict L = p.grad_v[0];
    const std::size_t n = p.size();
    const double c11 = c_.c11;
#pragma omp simd
    for (std::size_t q = 0; q < n; ++q) {
      eps[q] += dt * L[q];
      sig[q] = c11 * eps[q];
    }
  } else {
    if (axes_.size() != p.size() * Dim * Dim)
      throw RunError(fmt::format("cubic_elastic: {} points, but the crystal axes of {} (the points "
                                 "must keep their number and order)",
                                 p.size(), axes_.size() / (Dim * Dim)));
    const std::size_t n = p.size();
#pragma omp parallel for schedule(static) num_threads(this->threads_) if (this->threads_ > 1)
    for (std::size_t q = 0; q < n; ++q) {
      const Mat L = jaumann::gather<Dim>(p.grad_v, q);
      const Mat Rh = jaumann::half_step_rotation<Dim>(jaumann::spin<Dim>(L), dt);
      const Mat eps = jaumann::objective_step<Dim>(jaumann::gather<Dim>(p.strain, q), Rh,
                                                   dt * jaumann::rate_of_deformation<Dim>(L));
      jaumann::scatter<Dim>(0.5 * (eps + eps.transpose()), q, p.strain);
      Eigen::Map<Eigen::Matrix<double, Dim, Dim, Eigen::RowMajor>> Q(&axes_[q * Dim * Dim]);
      const Mat turned = Rh * (Rh * Q);
      Q = turned;
      set_stress(p, q);
    }
  }
}

template <int Dim>
double CubicElastic<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  return std::sqrt(c_.wave_modulus(Dim) / p.density(q));
}

template <int Dim>
double CubicElastic<Dim>::stored_energy(const Points<Dim>& p, std::size_t q) const {
  double w = 0.0;
  for (int k = 0; k < Dim * Dim; ++k) w += p.stress[k][q] * p.strain[k][q];
  return 0.5 * p.volume[q] * w;
}

template <int Dim>
double CubicElastic<Dim>::out_of_plane_stress(const Points<Dim>& p, std::size_t q) const {
  if constexpr (Dim == 1) return c_.c12 * p.strain[0][q];
  else if constexpr (Dim == 2) return c_.c12 * (p.strain[0][q] + p.strain[3][q]);  // tr eps: Q-invariant
  else return 0.0;
}

template <int Dim>
void CubicElastic<Dim>::save(std::ostream& out) const {
  const std::uint64_t n = axes_.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(axes_.data()), static_cast<std::streamsize>(n * sizeof(double)));
}

template <int Dim>
void CubicElastic<Dim>::load(std::istream& in) {
  const std::uint64_t n = read_count(in, sizeof(double), "cubic_elastic axes");
  if (n % (Dim * Dim) != 0 || (Dim == 1 && n != 0))
    throw InputError("checkpoint: the cubic_elastic crystal axes are missing or malformed");
  axes_.assign(n, 0.0);
  in.read(reinterpret_cast<char*>(axes_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  if (!in) throw InputError("checkpoint: the cubic_elastic crystal axes are truncated");
}

template class CubicElastic<1>;
template class CubicElastic<2>;
template class CubicElastic<3>;

double CubicElasticModel::wave_speed(int dim, double density, double) const {
  return std::sqrt(std::max(c.wave_modulus(dim), 0.0) / density);
}
std::vector<std::string> CubicElasticModel::check_notes() const {
  std::vector<std::string> r{fmt::format("cubic_elastic: C11 = {:.6g}, C12 = {:.6g}, C44 = {:.6g}, density {:.6g} "
                                         "({}; the cube axes along x, y, z), from {}",
                                         c.c11, c.c12, c.c44, rho, units.empty() ? "the deck's units" : units, source)};
  for (const std::string& w : warnings) r.push_back("warning: " + w);
  return r;
}

std::vector<std::pair<std::string, double>> CubicElasticModel::constants() const {
  return {{"c11", c.c11}, {"c12", c.c12}, {"c44", c.c44}, {"density", rho}};
}

std::unique_ptr<Material<1>> CubicElasticModel::make1() const { return std::make_unique<CubicElastic<1>>(c); }
std::unique_ptr<Material<2>> CubicElasticModel::make2() const { return std::make_unique<CubicElastic<2>>(c); }
std::unique_ptr<Material<3>> CubicElasticModel::make3() const { return std::make_unique<CubicElastic<3>>(c); }

CubicConstants read_cubic_constants(Table& m, const Context&) {
  CubicConstants c;
  c.c11 = m.number("c11");
  m.positive("c11", c.c11);
  c.c12 = m.number("c12");
  if (std::isfinite(c.c11) && std::isfinite(c.c12)) {  // else the missing key is the error
    m.check(c.c11 - c.c12 > 0.0, "c12",
            fmt::format("must be below c11 = {} (Born stability of a cubic crystal: c11 - c12 > 0)", c.c11));
    m.check(c.c11 + 2.0 * c.c12 > 0.0, "c12",
            fmt::format("must exceed -c11 / 2 = {} (Born stability: c11 + 2 c12 > 0)", -0.5 * c.c11));
  }
  c.c44 = m.number("c44");
  m.positive("c44", c.c44);
  return c;
}

std::shared_ptr<const Model> CubicElasticEntry::read(Table& m, const Context& ctx) {
  auto r = std::make_shared<CubicElasticModel>();
  r->units = ctx.units;
  if (m.choice("constants_from", {"deck", "potential"}, "deck") == "deck") {
    r->rho = m.number("density");
    m.positive("density", r->rho);
    r->c = read_cubic_constants(m, ctx);
    return r;
  }
  // The 0 K crystal of an MD potential (md/equilibrium.hpp): the constants the DDMP-MD
  // closure's crystal has, for the continuum baseline beside it (VALIDATION.md J4).
  for (const char* key : {"c11", "c12", "c44"})
    if (m.has(key)) m.check(false, key, "is taken from the potential (constants_from = \"potential\")");
  const auto u = units::unit_system(ctx.units);
  if (!u) {
    m.check(false, "constants_from",
            fmt::format("potential constants need case.units to be one of {}, not '{}'", units::unit_system_names(),
                        ctx.units));
    return r;
  }
  if (!ctx.crystal_of) {
    m.check(false, "constants_from", "potential constants need the MD engine, which this reader was not given");
    return r;
  }
  if (const auto crystal = ctx.crystal_of(m, "potential")) {
    r->c.c11 = crystal->c11;
    r->c.c12 = crystal->c12;
    r->c.c44 = crystal->c44;
    r->rho = crystal->density;
    r->source = crystal->source;
    r->warnings = crystal->warnings;
    // A crystal the potential does not hold together (a lattice the element does not
    // take) gives constants a cubic law cannot run with: refused, with them.
    const auto& k = r->c;
    m.check(k.c11 - k.c12 > 0 && k.c11 + 2 * k.c12 > 0 && k.c44 > 0, "potential",
            fmt::format("gives C11 = {:.4g}, C12 = {:.4g}, C44 = {:.4g} ({}) for {}: not Born-stable (C11 - C12 > 0, "
                        "C11 + 2 C12 > 0, C44 > 0 fail): not the element's crystal? (set `lattice` = \"{}\" beside "
                        "constants_from to take the other cubic one)",
                        k.c11, k.c12, k.c44, ctx.units, crystal->source,
                        crystal->source.find(" fcc ") != std::string::npos ? "bcc" : "fcc"));
  }
  if (m.has("density")) {  // the crystal's own unless the deck says otherwise
    r->rho = m.number("density");
    m.positive("density", r->rho);
  }
  return r;
}

}  // namespace mpmx::material
