#pragma once
// mie_gruneisen: a Mie-Gruneisen equation of state referenced to the linear Us-up
// Hugoniot (Us = c0 + s up), with an elastic-perfectly-plastic deviator.
//
// Pressure, eta = 1 - rho0 / rho (compression positive), e the specific internal energy:
//   p(eta, e) = p_H(eta) (1 - Gamma0 eta / 2) + Gamma0 rho0 e         (rho Gamma = rho0 Gamma0)
//   p_H(eta)  = rho0 c0^2 eta / (1 - s eta)^2    for eta >= 0 (the Hugoniot: on it
//               e_H = p_H (v0 - v) / 2 and p(eta, e_H) = p_H exactly),
//             = rho0 c0^2 eta                    for eta < 0 (a linear tension branch of
//               the reference curve; the formula for p is the same, so p is C1 at eta = 0).
// 1 - s eta must stay positive (the reference diverges at eta = 1 / s): a point that gets
// there stops the run with a RunError naming it and its compression.
//
// Deviator s (3x3, traceless): hypoelastic with the Jaumann rate (jaumann.hpp,
// Hughes-Winget), s_trial = Rh (Rh s Rh^T + 2 G dt dev(D)) Rh^T, then the von Mises
// radial return s = s_trial min(1, Y / sqrt(3/2 s_trial : s_trial)); Y = 0 gives a
// fluid (s = 0).
// 1-D is uniaxial strain (D = diag(L_xx, 0, 0): s_yy = s_zz = -s_xx / 2); 2-D is plane
// strain (D_zz = 0; s_zz is kept, so the yield surface sees the full deviator).
// Stress written to the points: sigma = -p I + s (the Dim x Dim block).
//
// Internal energy (per point, per unit mass) from the stress power sigma : D / rho over
// the step, trapezoidal in time and implicit in p^{n+1} (which depends on e^{n+1}):
//   e^{n+1} = e^n - (p^n + p^{n+1}) / 2 (v^{n+1} - v^n) + dt v^{n+1/2} (s^n + s^{n+1}) / 2 : D
// with v = V / m the specific volume of the point's actual volumes (so the spherical work
// is the -p dv the EOS sees, and one step across a jump satisfies the Rankine-Hugoniot
// energy condition exactly). The deviatoric work (elastic and plastic) is included, and
// the linear viscosity's q the step's forces used, -q (v^{n+1} - v^n). The tensor
// viscosity's work is deposited by the engine with add_viscous_work (a smeared shock
// left without it ends near the isentrope, not on the Hugoniot: copper compressed
// smoothly to the Hugoniot's eta at up = 1.25 km/s reaches a pressure 5.5% below
// rho0 Us up).
#include <array>
#include <memory>
#include <vector>

#include "mpmx/material/jaumann.hpp"
#include "mpmx/material/material.hpp"
#include "mpmx/material/model.hpp"

namespace mpmx::material {

struct MieGruneisenEos {
  double rho0 = 1.0, c0 = 1.0, s = 0.0, gamma0 = 0.0;

  // The reference Hugoniot p_H(eta) and its slope dp_H / deta.
  double hugoniot_pressure(double eta) const {
    const double k = rho0 * c0 * c0;
    if (eta < 0.0) return k * eta;
    const double d = 1.0 - s * eta;
    return k * eta / (d * d);
  }
  double hugoniot_slope(double eta) const {
    const double k = rho0 * c0 * c0;
    if (eta < 0.0) return k;
    const double d = 1.0 - s * eta;
    return k * (1.0 + s * eta) / (d * d * d);
  }
  // A(eta) = p_H (1 - Gamma0 eta / 2): the pressure at e = 0; and dA / deta.
  double reference_pressure(double eta) const { return hugoniot_pressure(eta) * (1.0 - 0.5 * gamma0 * eta); }
  double reference_slope(double eta) const {
    return hugoniot_slope(eta) * (1.0 - 0.5 * gamma0 * eta) - 0.5 * gamma0 * hugoniot_pressure(eta);
  }
  double pressure(double eta, double e) const { return reference_pressure(eta) + gamma0 * rho0 * e; }
  // The isentropic bulk modulus K = -V dp/dV along the current state. With v = 1/rho,
  // eta = 1 - rho0 v and de = -p dv on an isentrope:
  //   dp = A'(eta) deta + Gamma0 rho0 de = -rho0 (A'(eta) + Gamma0 p) dv,
  //   K  = -v dp/dv = (rho0 / rho) (A'(eta) + Gamma0 p)      (= rho0 c0^2 at rho0, e = 0).
  double bulk_modulus(double eta, double e) const {
    return (1.0 - eta) * (reference_slope(eta) + gamma0 * pressure(eta, e));
  }
  // Whether the reference is defined at eta (1 - s eta > 0; false for NaN).
  bool admissible(double eta) const { return 1.0 - s * eta > 0.0; }
};

struct MieGruneisenParams {
  MieGruneisenEos eos;
  double shear_modulus = 0.0;  // G
  double yield_stress = 0.0;   // Y (von Mises); 0: a fluid

  // rho v^2 of the longitudinal wave: K + 4 G / 3 (K alone when Y = 0: no shear stiffness).
  double wave_modulus(double eta, double e) const {
    return eos.bulk_modulus(eta, e) + (yield_stress > 0.0 ? 4.0 / 3.0 * shear_modulus : 0.0);
  }
};

template <int Dim>
class MieGruneisen final : public Material<Dim> {
 public:
  using Mat3 = jaumann::Mat<3>;

  explicit MieGruneisen(const MieGruneisenParams& m) : m_(m) {}

  std::string name() const override { return "mie_gruneisen"; }
  // e = 0 at every point; the density is the point's (mass / volume); the deviator is
  // 2 G dev(eps) of the initial strain array (uniaxial / plane strain), returned to Y.
  void initialize(const Points<Dim>& p) override;
  void update_stress(const Points<Dim>& p, double dt) override;
  // sqrt((K + 4 G / 3) / rho) at the point's density and energy (MieGruneisenParams).
  double sound_speed(const Points<Dim>& p, std::size_t q) const override;
  // m e: the internal energy of the point.
  bool keeps_energy_account() const override { return true; }
  double stored_energy(const Points<Dim>& p, std::size_t q) const override;
  // The specific internal energy e, the equivalent plastic strain (with Y > 0) and in 1-D
  // the lateral stresses sigma_yy, sigma_zz. No temperature: the law has no heat capacity.
  std::vector<PointField> point_fields(const Points<Dim>& p) const override;
  // e, v, the six deviator components and the plastic strain of every point, in point order.
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;
  long long state_points() const override { return static_cast<long long>(e_.size()); }

  // Adds the work of the viscous stress qv (Dim x Dim, what tensor_viscosity wrote) over
  // the step, dt qv : D / rho, to e, and the pressure it raises to the stress. Call it
  // after update_stress, with the same points and the qv of this step.
  void add_viscous_heat(const Points<Dim>& p, const std::array<double*, Dim * Dim>& q, double dt) override {
    add_viscous_work(p, q, dt);
  }
  template <class Ptr>
  void add_viscous_work(const Points<Dim>& p, const std::array<Ptr, Dim * Dim>& qv, double dt);

  const MieGruneisenParams& params() const { return m_; }
  double internal_energy(std::size_t q) const { return e_[q]; }        // per unit mass
  double specific_volume(std::size_t q) const { return v_[q]; }        // at the last update
  double pressure(std::size_t q) const { return m_.eos.pressure(eta_of(v_[q]), e_[q]); }
  Mat3 deviator(std::size_t q) const;
  // The full 3x3 Cauchy stress -p I + s (its out-of-plane parts are not in the points).
  Mat3 stress3(std::size_t q) const { return deviator(q) - pressure(q) * Mat3::Identity(); }

 private:
  void set_deviator(std::size_t q, const Mat3& s);
  void set_stress(const Points<Dim>& p, std::size_t q) const;
  double checked_eta(std::size_t q, double v) const;
  // eta = 1 - rho0 v of the volume per mass v, and whether the EOS holds there.
  double eta_of(double v) const { return 1.0 - m_.eos.rho0 * v; }
  bool admissible_volume(double v) const { return v > 0.0 && m_.eos.admissible(eta_of(v)); }

  MieGruneisenParams m_;
  std::vector<double> e_, v_;
  std::vector<std::array<double, 6>> s_;  // xx, yy, zz, xy, xz, yz
  std::vector<double> ep_;                 // equivalent plastic strain (output only)
};

extern template class MieGruneisen<1>;
extern template class MieGruneisen<2>;
extern template class MieGruneisen<3>;

template <int Dim>
template <class Ptr>
void MieGruneisen<Dim>::add_viscous_work(const Points<Dim>& p, const std::array<Ptr, Dim * Dim>& qv,
                                         double dt) {
  const std::size_t n = p.size();
#pragma omp parallel for schedule(static) num_threads(this->threads_) if (this->threads_ > 1)
  for (std::size_t q = 0; q < n; ++q) {
    double w = 0.0;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) w += qv[a * Dim + b][q] * 0.5 * (p.L(q, a, b) + p.L(q, b, a));
    e_[q] += dt * v_[q] * w;
    set_stress(p, q);
  }
}

// The [material] table of model = "mie_gruneisen".
struct MieGruneisenModel final : Model {
  MieGruneisenParams m;

  std::string name() const override { return "mie_gruneisen"; }
  double density() const override { return m.eos.rho0; }
  bool solid() const override { return true; }
  // rho0 is the EOS's reference density: a point at initial strain e starts at rho0 / (1 + e).
  bool density_of_unstrained() const override { return true; }
  // At density rho and pressure p: e from p = A(eta) + Gamma0 rho0 e (e = 0 if Gamma0 = 0),
  // then sqrt((K + 4 G / 3) / rho), the same in every dimension; NaN past eta = 1 / s.
  double wave_speed(int dim, double density, double pressure) const override;
  // The linear Us = c0 + s up Hugoniot's state and the wave speed there.
  Shocked shocked(int dim, double up) const override;
  std::unique_ptr<Material<1>> make1() const override;
  std::unique_ptr<Material<2>> make2() const override;
  std::unique_ptr<Material<3>> make3() const override;
};

// The registry entry (app/mpm/materials.hpp).
struct MieGruneisenEntry {
  static constexpr std::string_view name = "mie_gruneisen";
  static std::shared_ptr<const Model> read(Table& m, const Context& ctx);
};

}  // namespace mpmx::material
