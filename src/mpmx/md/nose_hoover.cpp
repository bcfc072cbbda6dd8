#include "mpmx/md/nose_hoover.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"

namespace mpmx::md {

NoseHoover::NoseHoover(const NoseHooverOptions& o, std::size_t atoms) : o_(o) {
  if (o.chain < 1) throw InputError(fmt::format("Nose-Hoover chain of {}: needs at least 1", o.chain));
  natoms_ = static_cast<double>(atoms);
  tdof_ = 3 * natoms_ - 3;  // the momentum's three fixed, as the temperature counts them
  if (!o.isotropic) {
    pdim_ = o.axes[0] + o.axes[1] + o.axes[2];
    if (pdim_ == 0) throw InputError("a per-axis barostat needs at least one axis that dilates");
  }
  if (o.hugoniot && (!o.barostat || !o.thermostat || o.isotropic || pdim_ != 1))
    throw InputError("a Hugoniostat needs the thermostat and a barostat along one axis");
  const int m = o.chain;
  eta_.assign(m, 0.0), eta_dot_.assign(m + 1, 0.0), eta_dotdot_.assign(m, 0.0);
  etap_.assign(m, 0.0), etap_dot_.assign(m + 1, 0.0), etap_dotdot_.assign(m, 0.0), etap_mass_.assign(m, 0.0);
}

NoseHoover::NoseHoover(const NoseHooverOptions& o, const System& s) : NoseHoover(o, s.atoms().size()) {
  // Without a thermostat (nph) the barostat's kT is the temperature the box starts at.
  const double t = o.thermostat ? o.temperature : s.temperature();
  if (!(t > 0)) throw InputError(fmt::format("temperature {} K: a Nose-Hoover chain needs a positive one", t));
  set_kt(units::boltzmann_eV_per_K * t);
  t_target_ = t;
  e0_ = s.potential_energy() + s.thermal_kinetic_energy(), v0_ = s.box().volume(), p0_ = axis_pressure(s);
  for (int k = 1; k < o.chain; ++k) eta_dotdot_[k] = -kt_ / eta_mass(k, kt_);  // eta_dot starts at 0
  for (int k = 1; k < o.chain; ++k) etap_dotdot_[k] = -kt_ / etap_mass_[k];
}

NoseHoover::NoseHoover(const NoseHooverOptions& o, std::size_t atoms, const std::vector<double>& v)
    : NoseHoover(o, atoms) {
  if (v.size() != state_size(o))
    throw InputError(fmt::format("Nose-Hoover state of {} numbers: expected {}", v.size(), state_size(o)));
  auto it = v.begin();
  for (auto* a : {&eta_, &eta_dot_, &eta_dotdot_, &etap_, &etap_dot_, &etap_dotdot_}) {
    std::copy(it, it + static_cast<std::ptrdiff_t>(a->size()), a->begin());
    it += static_cast<std::ptrdiff_t>(a->size());
  }
  std::copy(it, it + 3, omega_dot_.begin());
  mtk_term2_ = it[3], t_target_ = it[4];
  if (!(it[5] > 0)) throw InputError(fmt::format("Nose-Hoover kT of {} eV: needs a positive one", it[5]));
  set_kt(it[5]);
  e0_ = it[6], v0_ = it[7], p0_ = it[8];
}

// Masses from the periods: the barostat's W = (N + 1) kT / omega^2, its chain's kT / omega^2.
void NoseHoover::set_kt(double kt) {
  kt_ = kt;
  const double pf = 1 / o_.p_damp;
  for (int i = 0; i < 3; ++i) omega_mass_[i] = (natoms_ + 1) * kt_ / (pf * pf);
  for (auto& q : etap_mass_) q = kt_ / (pf * pf);
}

double NoseHoover::axis_pressure(const System& s) const {
  const Mat3 sigma = s.stress();
  if (o_.isotropic || pdim_ != 1) return -(sigma[0] + sigma[4] + sigma[8]) / 3;
  const int i = o_.axes[0] ? 0 : o_.axes[1] ? 1 : 2;
  return -sigma[4 * i];
}

// Q_0 = N_f kT / omega^2 and Q_k = kT / omega^2, omega = 1 / t_damp.
double NoseHoover::eta_mass(int k, double kt) const {
  const double tf = 1 / o_.t_damp;
  return (k == 0 ? tdof_ : 1.0) * kt / (tf * tf);
}

void NoseHoover::initial(System& s, double dt) {
  if (o_.barostat) barostat_chain(dt);
  if (o_.hugoniot) {
    // LAMMPS's fix nphug: the target is the temperature now plus the Hugoniot energy's
    // excess over the energy now, as heat of the thermostatted degrees of freedom.
    const double e = s.potential_energy() + s.thermal_kinetic_energy(), v = s.box().volume();
    const double excess = 0.5 * (axis_pressure(s) + p0_) * (v0_ - v) + e0_ - e;
    t_target_ = s.temperature() + excess / (tdof_ * units::boltzmann_eV_per_K);
  }
  if (o_.thermostat) thermostat_chain(s, dt);
  if (o_.barostat) {
    omega_force(s, dt);
    v_press(s, dt);
  }
}

void NoseHoover::remap(System& s, double dt) {
  if (!o_.barostat) return;
  s.dilate({std::exp(0.5 * dt * omega_dot_[0]), std::exp(0.5 * dt * omega_dot_[1]), std::exp(0.5 * dt * omega_dot_[2])});
}

void NoseHoover::final(System& s, double dt) {
  if (o_.barostat) {
    v_press(s, dt);
    omega_force(s, dt);
  }
  if (o_.thermostat) thermostat_chain(s, dt);
  if (o_.barostat) barostat_chain(dt);
}

// Half a step of the thermostat chain, from its far end in and back out (Tuckerman et
// al. 2006, eq. 43), the atoms' velocities scaled at its middle.
void NoseHoover::thermostat_chain(System& s, double dt) {
  const int m = o_.chain;
  // Masses from the target now (LAMMPS keeps the chain's periods as its target moves).
  const double kt = units::boltzmann_eV_per_K * t_target_;
  const double dt4 = 0.25 * dt, dt8 = 0.125 * dt, ke_target = tdof_ * kt;
  double ke = 2 * s.thermal_kinetic_energy();  // N_f k T
  eta_dotdot_[0] = (ke - ke_target) / eta_mass(0, kt);
  for (int k = m - 1; k > 0; --k) {
    const double e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
  double e = std::exp(-dt8 * eta_dot_[1]);
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  const double f = std::exp(-0.5 * dt * eta_dot_[0]);
  s.scale_velocities({f, f, f});
  ke *= f * f;
  eta_dotdot_[0] = (ke - ke_target) / eta_mass(0, kt);
  for (int k = 0; k < m; ++k) eta_[k] += 0.5 * dt * eta_dot_[k];
  eta_dot_[0] = (eta_dot_[0] * e + eta_dotdot_[0] * dt4) * e;
  for (int k = 1; k < m; ++k) {
    e = std::exp(-dt8 * eta_dot_[k + 1]);
    eta_dotdot_[k] = (eta_mass(k - 1, kt) * eta_dot_[k - 1] * eta_dot_[k - 1] - kt) / eta_mass(k, kt);
    eta_dot_[k] = (eta_dot_[k] * e + eta_dotdot_[k] * dt4) * e;
  }
}

// The same for the chain on the barostat's own motion; LAMMPS's target for it: kT for
// an isotropic barostat, 3 kT for one per axis.
void NoseHoover::barostat_chain(double dt) {
  const int m = o_.chain;
  const double dt4 = 0.25 * dt, dt8 = 0.125 * dt, target = o_.isotropic ? kt_ : pdim_ * kt_;
  auto ke = [&] {
    double k = 0;
    for (int i = 0; i < 3; ++i) k += omega_mass_[i] * omega_dot_[i] * omega_dot_[i];  // 0 off the axes
    return k;
  };
  etap_dotdot_[0] = (ke() - target) / etap_mass_[0];
  for (int k = m - 1; k > 0; --k) {
    const double e = std::exp(-dt8 * etap_dot_[k + 1]);
    etap_dot_[k] = (etap_dot_[k] * e + etap_dotdot_[k] * dt4) * e;
  }
  double e = std::exp(-dt8 * etap_dot_[1]);
  etap_dot_[0] = (etap_dot_[0] * e + etap_dotdot_[0] * dt4) * e;
  for (int k = 0; k < m; ++k) etap_[k] += 0.5 * dt * etap_dot_[k];
  const double f = std::exp(-0.5 * dt * etap_dot_[0]);
  for (auto& w : omega_dot_) w *= f;
  etap_dotdot_[0] = (ke() - target) / etap_mass_[0];
  etap_dot_[0] = (etap_dot_[0] * e + etap_dotdot_[0] * dt4) * e;
  for (int k = 1; k < m; ++k) {
    e = std::exp(-dt8 * etap_dot_[k + 1]);
    etap_dotdot_[k] = (etap_mass_[k - 1] * etap_dot_[k - 1] * etap_dot_[k - 1] - kt_) / etap_mass_[k];
    etap_dot_[k] = (etap_dot_[k] * e + etap_dotdot_[k] * dt4) * e;
  }
}

// Half a step of the barostat's strain rates under the pressure's excess over its
// target and MTK's kinetic term (Martyna, Tobias, Klein 1994): an axis stops dilating
// where its pressure (the mean one, isotropic) equals its target.
void NoseHoover::omega_force(const System& s, double dt) {
  const Mat3 sigma = s.stress();  // eV/A^3, tension positive: pressure = -sigma
  const double v = s.box().volume();
  double p[3] = {-sigma[0], -sigma[4], -sigma[8]};
  double target[3];
  for (int i = 0; i < 3; ++i) target[i] = o_.pressure[i] / units::eV_per_A3_in_GPa;
  double mtk1;
  if (o_.isotropic) {
    const double mean = (p[0] + p[1] + p[2]) / 3, mean_target = (target[0] + target[1] + target[2]) / 3;
    for (int i = 0; i < 3; ++i) p[i] = mean, target[i] = mean_target;
    mtk1 = 2 * s.thermal_kinetic_energy() / (3 * natoms_);
  } else {
    const Vec3 k = s.mvv();
    mtk1 = 0;
    for (int i = 0; i < 3; ++i) mtk1 += o_.axes[i] ? k[i] : 0.0;
    mtk1 /= pdim_ * natoms_;
  }
  for (int i = 0; i < 3; ++i)
    if (o_.isotropic || o_.axes[i]) omega_dot_[i] += ((p[i] - target[i]) * v + mtk1) / omega_mass_[i] * 0.5 * dt;
  mtk_term2_ = (omega_dot_[0] + omega_dot_[1] + omega_dot_[2]) / (pdim_ * natoms_);
}

// The atoms' velocities damped by the box's dilation over half a step.
void NoseHoover::v_press(System& s, double dt) {
  Vec3 f;
  for (int i = 0; i < 3; ++i) f[i] = std::exp(-0.5 * dt * (omega_dot_[i] + mtk_term2_));
  s.scale_velocities(f);
}

std::vector<double> NoseHoover::state() const {
  std::vector<double> v;
  for (const auto* a : {&eta_, &eta_dot_, &eta_dotdot_, &etap_, &etap_dot_, &etap_dotdot_}) v.insert(v.end(), a->begin(), a->end());
  v.insert(v.end(), omega_dot_.begin(), omega_dot_.end());
  for (double x : {mtk_term2_, t_target_, kt_, e0_, v0_, p0_}) v.push_back(x);
  return v;
}

}  // namespace mpmx::md
