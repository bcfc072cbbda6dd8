#include "mpmx/material/mie_gruneisen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/binary.hpp"

namespace mpmx::material {

namespace {

// The von Mises radial return of a trial deviator to the yield stress Y.
jaumann::Mat<3> radial_return(const jaumann::Mat<3>& trial, double Y) {
  const double vm = std::sqrt(1.5 * trial.squaredNorm());
  if (vm <= Y) return trial;
  if (Y <= 0.0) return jaumann::Mat<3>::Zero();
  return (Y / vm) * trial;
}

}  // namespace

template <int Dim>
typename MieGruneisen<Dim>::Mat3 MieGruneisen<Dim>::deviator(std::size_t q) const {
  const auto& c = s_[q];
  Mat3 s;
  s << c[0], c[3], c[4],
       c[3], c[1], c[5],
       c[4], c[5], c[2];
  return s;
}

template <int Dim>
void MieGruneisen<Dim>::set_deviator(std::size_t q, const Mat3& s) {
  const Mat3 sym = 0.5 * (s + s.transpose());
  const Mat3 d = jaumann::deviator(sym);  // traceless to round-off, step after step
  s_[q] = {d(0, 0), d(1, 1), d(2, 2), d(0, 1), d(0, 2), d(1, 2)};
}

template <int Dim>
void MieGruneisen<Dim>::set_stress(const Points<Dim>& p, std::size_t q) const {
  const Mat3 s = deviator(q);
  const double pr = pressure(q);
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) p.stress[a * Dim + b][q] = s(a, b) - (a == b ? pr : 0.0);
  p.set_sigma_zz(q, s(2, 2) - pr);  // the deviator is kept whole (3 x 3)
}

template <int Dim>
double MieGruneisen<Dim>::checked_eta(std::size_t q, double v) const {
  const double eta = eta_of(v);
  if (!admissible_volume(v))
    throw RunError(fmt::format(
        "mie_gruneisen: point {} is compressed to rho / rho0 = {:.6g} (eta = 1 - rho0 / rho = {:.6g}): "
        "1 - s eta = {:.3g} is not positive, past the Hugoniot reference's limit eta = 1 / s = {:.6g} "
        "(volume per mass {:.6g})",
        q, 1.0 / (m_.eos.rho0 * v), eta, 1.0 - m_.eos.s * eta,
        m_.eos.s > 0.0 ? 1.0 / m_.eos.s : HUGE_VAL, v));
  return eta;
}

template <int Dim>
void MieGruneisen<Dim>::initialize(const Points<Dim>& p) {
  const std::size_t n = p.size();
  e_.assign(n, 0.0);
  v_.assign(n, 0.0);
  s_.assign(n, {});
  ep_.assign(n, 0.0);
  const double G = m_.shear_modulus;
  for (std::size_t q = 0; q < n; ++q) {
    v_[q] = p.volume[q] / p.mass[q];
    checked_eta(q, v_[q]);
    const Mat3 eps = jaumann::embed<Dim>(jaumann::gather<Dim>(p.strain, q));
    set_deviator(q, radial_return(jaumann::deviator(2.0 * G * eps), m_.yield_stress));
    set_stress(p, q);
  }
}

template <int Dim>
void MieGruneisen<Dim>::update_stress(const Points<Dim>& p, double dt) {
  using MatD = jaumann::Mat<Dim>;
  if (e_.size() != p.size())
    throw RunError(fmt::format("mie_gruneisen: {} points, but the state of {} (the points must keep "
                               "their number and order)",
                               p.size(), e_.size()));
  const auto& eos = m_.eos;
  const double G = m_.shear_modulus, Y = m_.yield_stress;
  const double B = eos.gamma0 * eos.rho0;  // dp / de at constant volume
  const std::size_t n = p.size();
  // Every point's new volume is checked before any point changes, so a point past the
  // Hugoniot reference's limit stops the run with the state whole, named by the lowest
  // index on any thread count.
  std::size_t past = n;
#pragma omp parallel for schedule(static) reduction(min : past) num_threads(this->threads_) if (this->threads_ > 1)
  for (std::size_t q = 0; q < n; ++q)
    if (!admissible_volume(p.volume[q] / p.mass[q])) past = std::min(past, q);
  if (past < n) checked_eta(past, p.volume[past] / p.mass[past]);  // throws, naming it
#pragma omp parallel for schedule(static) num_threads(this->threads_) if (this->threads_ > 1)
  for (std::size_t q = 0; q < n; ++q) {
    const MatD L = jaumann::gather<Dim>(p.grad_v, q);
    const MatD D = jaumann::rate_of_deformation<Dim>(L);
    const MatD Rh = jaumann::half_step_rotation<Dim>(jaumann::spin<Dim>(L), dt);
    // The strain array: the same objective step (an output measure here).
    const MatD eps = jaumann::objective_step<Dim>(jaumann::gather<Dim>(p.strain, q), Rh, dt * D);
    jaumann::scatter<Dim>(0.5 * (eps + eps.transpose()), q, p.strain);

    // Deviator: the Jaumann step of the elastic trial, then the return to the yield
    // surface (which commutes with the rotation).
    const Mat3 D3 = jaumann::embed<Dim>(D);
    Mat3 Rh3 = Mat3::Identity();  // the spin is in the Dim x Dim block only
    Rh3.template topLeftCorner<Dim, Dim>() = Rh;
    const Mat3 s_old = deviator(q);
    const Mat3 trial = jaumann::objective_step<3>(s_old, Rh3, (2.0 * G * dt) * jaumann::deviator(D3));
    const Mat3 s_trial = jaumann::deviator(trial);
    // The equivalent plastic strain of the return, (|s_trial|_vM - Y) / 3G (output only).
    const double vm = std::sqrt(1.5 * s_trial.squaredNorm());
    if (Y > 0.0 && vm > Y) ep_[q] += (vm - Y) / (3.0 * G);
    set_deviator(q, radial_return(s_trial, Y));
    const Mat3 s_new = deviator(q);

    // Energy and pressure, implicit in p^{n+1} = A(eta^{n+1}) + B e^{n+1}.
    const double v_old = v_[q];
    const double v_new = p.volume[q] / p.mass[q];
    const double eta_new = eta_of(v_new);  // admissible: checked above
    const double p_old = eos.pressure(eta_of(v_old), e_[q]);
    const double A_new = eos.reference_pressure(eta_new);
    const double dv = v_new - v_old;
    const double w_dev = dt * 0.5 * (v_old + v_new) * 0.5 * (s_old + s_new).cwiseProduct(D3).sum();
    // The linear viscosity's q (ch. 6), as the step's forces used it, heats as a pressure
    // would: without it a smeared shock ends near the isentrope (the 1-D copper bar at
    // 2.5 km/s: 2/3 of the jump's energy, its plateau 10% under rho0 Us up).
    const double w_q = p.viscous_pressure ? -p.viscous_pressure[q] * dv : 0.0;
    e_[q] = (e_[q] - 0.5 * (p_old + A_new) * dv + w_dev + w_q) / (1.0 + 0.5 * B * dv);
    v_[q] = v_new;
    set_stress(p, q);
  }
}

template <int Dim>
double MieGruneisen<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  const double rho = p.density(q);
  const double M = m_.wave_modulus(1.0 - m_.eos.rho0 / rho, e_[q]);
  return std::sqrt(std::max(M, 0.0) / rho);  // K < 0 only deep in tension
}

template <int Dim>
double MieGruneisen<Dim>::stored_energy(const Points<Dim>& p, std::size_t q) const {
  return p.mass[q] * e_[q];
}

template <int Dim>
std::vector<PointField> MieGruneisen<Dim>::point_fields(const Points<Dim>&) const {
  const std::size_t n = e_.size();
  std::vector<PointField> f{{"internal_energy", e_}};
  if (m_.yield_stress > 0.0) f.push_back({"plastic_strain", ep_});
  if constexpr (Dim == 1) {
    // Uniaxial strain: the lateral stresses -p + s_yy and -p + s_zz the points do not keep.
    PointField yy{"stress_yy", std::vector<double>(n)}, zz{"stress_zz", std::vector<double>(n)};
    for (std::size_t q = 0; q < n; ++q) {
      const Mat3 s = stress3(q);
      yy.values[q] = s(1, 1), zz.values[q] = s(2, 2);
    }
    f.push_back(std::move(yy));
    f.push_back(std::move(zz));
  }
  return f;
}

template <int Dim>
void MieGruneisen<Dim>::save(std::ostream& out) const {
  const std::uint64_t n = e_.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(e_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  out.write(reinterpret_cast<const char*>(v_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  out.write(reinterpret_cast<const char*>(s_.data()), static_cast<std::streamsize>(n * sizeof(s_[0])));
  out.write(reinterpret_cast<const char*>(ep_.data()), static_cast<std::streamsize>(n * sizeof(double)));
}

template <int Dim>
void MieGruneisen<Dim>::load(std::istream& in) {
  const std::uint64_t n = read_count(in, 3 * sizeof(double) + sizeof(s_[0]), "mie_gruneisen points");
  e_.assign(n, 0.0);
  v_.assign(n, 0.0);
  s_.assign(n, {});
  ep_.assign(n, 0.0);
  in.read(reinterpret_cast<char*>(e_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  in.read(reinterpret_cast<char*>(v_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  in.read(reinterpret_cast<char*>(s_.data()), static_cast<std::streamsize>(n * sizeof(s_[0])));
  in.read(reinterpret_cast<char*>(ep_.data()), static_cast<std::streamsize>(n * sizeof(double)));
  if (!in) throw InputError("checkpoint: the mie_gruneisen state is truncated");
}

template class MieGruneisen<1>;
template class MieGruneisen<2>;
template class MieGruneisen<3>;

double MieGruneisenModel::wave_speed(int, double density, double pressure) const {
  const auto& eos = m.eos;
  const double eta = 1.0 - eos.rho0 / density;
  if (!eos.admissible(eta)) return std::nan("");
  const double B = eos.gamma0 * eos.rho0;
  const double e = B > 0.0 ? (pressure - eos.reference_pressure(eta)) / B : 0.0;
  return std::sqrt(std::max(m.wave_modulus(eta, e), 0.0) / density);
}
Model::Shocked MieGruneisenModel::shocked(int dim, double up) const {
  const auto& eos = m.eos;
  const double us = eos.c0 + eos.s * std::abs(up), J = 1.0 - std::abs(up) / us;
  return {J, wave_speed(dim, eos.rho0 / J, eos.rho0 * us * std::abs(up)), true};
}
std::unique_ptr<Material<1>> MieGruneisenModel::make1() const { return std::make_unique<MieGruneisen<1>>(m); }
std::unique_ptr<Material<2>> MieGruneisenModel::make2() const { return std::make_unique<MieGruneisen<2>>(m); }
std::unique_ptr<Material<3>> MieGruneisenModel::make3() const { return std::make_unique<MieGruneisen<3>>(m); }

std::shared_ptr<const Model> MieGruneisenEntry::read(Table& t, const Context&) {
  auto r = std::make_shared<MieGruneisenModel>();
  auto& eos = r->m.eos;
  eos.rho0 = t.number("density");
  t.positive("density", eos.rho0);
  eos.c0 = t.number("sound_speed");
  t.positive("sound_speed", eos.c0);
  eos.s = t.number("slope");
  t.non_negative("slope", eos.s);
  eos.gamma0 = t.number("gruneisen");
  t.non_negative("gruneisen", eos.gamma0);
  r->m.shear_modulus = t.number("shear_modulus");
  t.non_negative("shear_modulus", r->m.shear_modulus);
  r->m.yield_stress = t.number("yield_stress");
  t.non_negative("yield_stress", r->m.yield_stress);
  if (r->m.yield_stress > 0.0)
    t.check(r->m.shear_modulus > 0.0, "shear_modulus",
            fmt::format("must be positive when yield_stress = {} > 0 (no deviator could build up; "
                        "yield_stress = 0 makes a fluid)",
                        r->m.yield_stress));
  return r;
}

}  // namespace mpmx::material
