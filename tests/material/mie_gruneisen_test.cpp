// ctest-label: unit
// mie_gruneisen (material/mie_gruneisen.*): the Hugoniot-referenced EOS, a
// Rankine-Hugoniot jump in copper, uniaxial compression against the integrated work
// (-p dv along the path), the von Mises cap, e equal to the stress work, the sound
// speed, the run-time limit 1 - s eta > 0, save/load, the viscous work, the deck table.
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "mpmx/core/error.hpp"
#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/io/deck.hpp"
#include "mpmx/material/mie_gruneisen.hpp"
#include "point_set.hpp"

namespace mpmx::material {
namespace {

using test::PointSet;
using Eigen::Matrix3d;

// Copper (N6): g/cm^3, km/s, GPa; e in GPa cm^3/g (kJ/g).
MieGruneisenParams copper(double yield = 0.12) {
  MieGruneisenParams m;
  m.eos = {8.93, 3.94, 1.49, 1.99};
  m.shear_modulus = 45.0;
  m.yield_stress = yield;
  return m;
}

TEST(MieGruneisenEos, HugoniotStateOfCopperAt1250MetresPerSecond) {
  const auto eos = copper().eos;
  const double up = 1.25, Us = eos.c0 + eos.s * up, etaH = up / Us;
  EXPECT_NEAR(Us, 5.8025, 1e-12);
  const double pH = eos.hugoniot_pressure(etaH);
  EXPECT_NEAR(pH / (eos.rho0 * Us * up), 1.0, 1e-12);
  EXPECT_NEAR(pH, 64.77, 0.01);  // VALIDATION N6: 64.8 GPa
  // On the Hugoniot (e_H = p_H (v0 - v) / 2 from rest) the EOS gives p_H back.
  const double eH = 0.5 * pH * etaH / eos.rho0;
  EXPECT_NEAR(eos.pressure(etaH, eH) / pH, 1.0, 1e-12);
  // The bulk modulus: rho0 c0^2 at the reference state; -V dp/dV along an isentrope
  // (de = -p dv) elsewhere, against a central difference.
  EXPECT_NEAR(eos.bulk_modulus(0.0, 0.0), eos.rho0 * eos.c0 * eos.c0, 1e-12);
  for (const double eta : {-0.05, 0.1, etaH, 0.4}) {
    const double e = 0.3, v = (1 - eta) / eos.rho0, h = 1e-6 * v;
    const double p0 = eos.pressure(eta, e);
    const double pp = eos.pressure(1 - eos.rho0 * (v + h), e - p0 * h);
    const double pm = eos.pressure(1 - eos.rho0 * (v - h), e + p0 * h);
    const double K = -v * (pp - pm) / (2 * h);
    EXPECT_NEAR(eos.bulk_modulus(eta, e) / K, 1.0, 1e-7) << "eta " << eta;
  }
  // The tension branch is linear and meets the compression branch with the same slope.
  EXPECT_NEAR(eos.hugoniot_pressure(-0.01), -0.01 * eos.rho0 * eos.c0 * eos.c0, 1e-14);
  EXPECT_EQ(eos.hugoniot_slope(-1e-300), eos.hugoniot_slope(0.0));
}

// One step of uniaxial compression along x from rest to eta, with the strain increment
// L_xx dt = (v - v0) / v_mid that the point's volumes imply.
template <int Dim>
void jump(double eta, PointSet<Dim>& pts, MieGruneisen<Dim>& law) {
  auto p = pts.view();
  law.initialize(p);
  const double V0 = pts.volume[0], V = V0 * (1 - eta), dt = 1e-3;
  typename PointSet<Dim>::Mat L = PointSet<Dim>::Mat::Zero();
  L(0, 0) = 2 * (V - V0) / (V + V0) / dt;
  pts.set_grad_v(L);
  pts.volume[0] = V;
  law.update_stress(p, dt);
}

template <int Dim>
void rankine_hugoniot() {
  const double up = 1.25;
  for (const double Y : {0.0, 0.12}) {
    const auto m = copper(Y);
    const auto& eos = m.eos;
    const double Us = eos.c0 + eos.s * up, etaH = up / Us, v0 = 1 / eos.rho0;
    PointSet<Dim> pts(1, eos.rho0);
    MieGruneisen<Dim> law(m);
    jump<Dim>(etaH, pts, law);
    const double sxx = pts.stress(0)(0, 0);
    // The step satisfies the energy jump condition e = -sigma_xx (v0 - v) / 2 exactly.
    EXPECT_NEAR(law.internal_energy(0) / (-0.5 * sxx * etaH * v0), 1.0, 1e-12);
    // Y = 0: sigma_xx = -rho0 Us up. Y > 0: the deviator s_xx = -2Y/3 adds to the
    // Hugoniot stress, and its work heats: p - p_H = Gamma0 Y eta / 3 / (1 - Gamma0 eta / 2).
    const double heat = eos.gamma0 * Y * etaH / 3 / (1 - 0.5 * eos.gamma0 * etaH);
    const double expect = -(eos.rho0 * Us * up) - 2 * Y / 3 - heat;
    EXPECT_NEAR(sxx / expect, 1.0, 1e-12) << "Dim " << Dim << " Y " << Y;
    EXPECT_NEAR(law.deviator(0)(0, 0), -2 * Y / 3, 1e-12);
    EXPECT_NEAR(law.pressure(0), eos.rho0 * Us * up + heat, 1e-12 * 64.8);
    for (int a = 1; a < Dim; ++a) EXPECT_NEAR(pts.stress(0)(a, a), -law.pressure(0) + Y / 3, 1e-12 * 64.8);
    if (Y > 0) {
      EXPECT_NEAR(heat, 0.0218, 0.0001);
    }
  }
}

TEST(MieGruneisen, RankineHugoniotJumpInCopper) {
  rankine_hugoniot<1>();
  rankine_hugoniot<2>();
  rankine_hugoniot<3>();
}

// de/dv = -p(v, e) from v0 to v (no deviator), by RK4 in fine steps: the reference for
// the energy of a smooth uniaxial compression.
double isentrope_energy(const MieGruneisenEos& eos, double v_end) {
  const double v0 = 1 / eos.rho0;
  const int n = 200000;
  const double h = (v_end - v0) / n;
  auto f = [&](double v, double e) { return -eos.pressure(1 - eos.rho0 * v, e); };
  double e = 0.0, v = v0;
  for (int i = 0; i < n; ++i, v = v0 + i * h) {
    const double k1 = f(v, e), k2 = f(v + h / 2, e + h / 2 * k1), k3 = f(v + h / 2, e + h / 2 * k2),
                 k4 = f(v + h, e + h * k3);
    e += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return e;
}

template <int Dim>
void compress_to(double eta_end) {
  const auto m = copper(0.0);  // Y = 0: no deviator
  const auto& eos = m.eos;
  PointSet<Dim> pts(1, eos.rho0);
  MieGruneisen<Dim> law(m);
  auto p = pts.view();
  law.initialize(p);
  const int steps = 1000;
  const double dt = 1e-3;
  // Volume by the midpoint rule, V^{n+1} = V^n (1 + a) / (1 - a), a = dt L_xx / 2,
  // reaching V0 (1 - eta_end) in `steps` steps at a constant strain rate.
  const double r = std::pow(1 - eta_end, 1.0 / steps), a = (r - 1) / (r + 1);
  typename PointSet<Dim>::Mat L = PointSet<Dim>::Mat::Zero();
  L(0, 0) = 2 * a / dt;
  pts.set_grad_v(L);
  for (int k = 0; k < steps; ++k) {
    pts.volume[0] *= (1 + a) / (1 - a);
    law.update_stress(p, dt);
    const double eta = 1 - eos.rho0 * pts.volume[0] / pts.mass[0];
    ASSERT_NEAR(pts.stress(0)(0, 0), -eos.pressure(eta, law.internal_energy(0)), 1e-12 * 60);
  }
  const double eta = 1 - eos.rho0 * pts.volume[0] / pts.mass[0];
  EXPECT_NEAR(eta, eta_end, 1e-12);
  const double e_ref = isentrope_energy(eos, pts.volume[0] / pts.mass[0]);
  EXPECT_NEAR(law.internal_energy(0) / e_ref, 1.0, 1e-6) << "Dim " << Dim;
  EXPECT_NEAR(law.pressure(0), eos.pressure(eta, law.internal_energy(0)), 1e-12 * 60);
  for (int a = 0; a < Dim; ++a) EXPECT_EQ(pts.stress(0)(a, a), pts.stress(0)(0, 0));
  EXPECT_EQ(law.stored_energy(p, 0), pts.mass[0] * law.internal_energy(0));
  // Smooth compression stays below the Hugoniot at the same eta (less heating).
  EXPECT_LT(law.pressure(0), eos.hugoniot_pressure(eta));
  // The sound speed: sqrt(K / rho) (Y = 0: no shear part), as the model's wave speed.
  const double rho = pts.mass[0] / pts.volume[0];
  EXPECT_NEAR(law.sound_speed(p, 0), std::sqrt(eos.bulk_modulus(eta, law.internal_energy(0)) / rho), 1e-12);
  MieGruneisenModel model;
  model.m = m;
  EXPECT_NEAR(model.wave_speed(Dim, rho, law.pressure(0)), law.sound_speed(p, 0), 1e-12);
}

TEST(MieGruneisen, UniaxialCompressionFollowsTheEosWithTheIntegratedWork) {
  compress_to<1>(0.2);
  compress_to<2>(0.2);
  compress_to<3>(0.2);
  compress_to<3>(0.05);
}

TEST(MieGruneisen, SoundSpeedAtRest) {
  PointSet<2> pts(1, 8.93);
  MieGruneisen<2> solid(copper()), fluid(copper(0.0));
  auto p = pts.view();
  solid.initialize(p);
  fluid.initialize(p);
  EXPECT_NEAR(solid.sound_speed(p, 0), std::sqrt((8.93 * 3.94 * 3.94 + 4.0 / 3 * 45.0) / 8.93), 1e-12);
  EXPECT_NEAR(fluid.sound_speed(p, 0), 3.94, 1e-12);
}

// Simple shear with some compression (and spin): the von Mises stress never exceeds Y.
template <int Dim>
void yield_capped() {
  const auto m = copper();
  const double Y = m.yield_stress;
  PointSet<Dim> pts(1, m.eos.rho0);
  MieGruneisen<Dim> law(m);
  auto p = pts.view();
  law.initialize(p);
  typename PointSet<Dim>::Mat L = PointSet<Dim>::Mat::Zero();
  L(0, 0) = -0.05;
  if constexpr (Dim > 1) L(0, 1) = 1.0;
  pts.set_grad_v(L);
  const double dt = 1e-3;
  double worst = 0.0;
  for (int k = 0; k < 2000; ++k) {
    pts.volume[0] *= (1 + 0.5 * dt * L.trace()) / (1 - 0.5 * dt * L.trace());
    law.update_stress(p, dt);
    const double vm = jaumann::von_mises(law.stress3(0));
    worst = std::max(worst, vm);
    if constexpr (Dim == 3) {
      ASSERT_NEAR(jaumann::von_mises(pts.stress(0)), vm, 1e-12 * Y);
    }
    if (k == 0) {  // elastic: the first step's deviator is Rh 2 G dt dev(D) Rh^T
      EXPECT_LT(vm, Y);
      const Matrix3d D = jaumann::embed<Dim>(typename PointSet<Dim>::Mat(0.5 * (L + L.transpose())));
      Matrix3d Rh = Matrix3d::Identity();
      Rh.template topLeftCorner<Dim, Dim>() =
          jaumann::half_step_rotation<Dim>(0.5 * (L - L.transpose()), dt);
      const Matrix3d s1 = Rh * (2 * m.shear_modulus * dt * jaumann::deviator(D)) * Rh.transpose();
      EXPECT_LT((law.deviator(0) - s1).norm(), 1e-15);
      if constexpr (Dim > 1) {  // 2 G gamma_dot dt / 2, turned by Rh: 2.5e-5 relative
        EXPECT_NEAR(pts.stress(0)(0, 1), 2 * m.shear_modulus * dt * 0.5, 3e-5 * 0.045);
      }
    }
  }
  EXPECT_LE(worst, Y * (1 + 1e-12)) << "Dim " << Dim;
  EXPECT_NEAR(jaumann::von_mises(law.stress3(0)), Y, 1e-12 * Y);  // flowing at the end
  EXPECT_NEAR(law.deviator(0).trace(), 0.0, 1e-15);
  if constexpr (Dim == 1) {
    EXPECT_NEAR(law.deviator(0)(0, 0), -2 * Y / 3, 1e-12 * Y);
  }
}

TEST(MieGruneisen, VonMisesStressNeverExceedsTheYieldStress) {
  yield_capped<1>();
  yield_capped<2>();
  yield_capped<3>();
}

// e equals the stress work per unit mass, sum of dt v_mid (sigma^n + sigma^{n+1}) / 2 : D,
// over a path of compression, shear, spin and some expansion, elastic and plastic.
// With a linear viscosity q (ch. 6) the step's forces also did -q (v_new - v_old), which
// is heat in e as well.
template <int Dim>
void energy_is_the_work(double Y, double q = 0.0) {
  auto m = copper(Y);
  PointSet<Dim> pts(1, m.eos.rho0);
  MieGruneisen<Dim> law(m);
  auto p = pts.view();
  const std::vector<double> viscous{q};
  if (q > 0.0) p.viscous_pressure = viscous.data();
  law.initialize(p);
  std::mt19937_64 rng(Dim);
  std::normal_distribution<double> n01;
  const double dt = 1e-3;
  double work = 0.0;
  for (int k = 0; k < 1000; ++k) {
    typename PointSet<Dim>::Mat L;
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) L(a, b) = 0.3 * n01(rng) + (a == b ? -0.2 : 0.0);
    pts.set_grad_v(L);
    const double t = 0.5 * dt * L.trace();
    const double v_old = pts.volume[0] / pts.mass[0];
    const auto s_old = pts.stress(0);
    pts.volume[0] *= (1 + t) / (1 - t);  // then (v_new - v_old) / v_mid = dt tr D
    law.update_stress(p, dt);
    const double v_mid = 0.5 * (v_old + pts.volume[0] / pts.mass[0]);
    const auto D = 0.5 * (L + L.transpose());
    work += dt * v_mid * (0.5 * (s_old + pts.stress(0))).cwiseProduct(D).sum();
    work -= q * (pts.volume[0] / pts.mass[0] - v_old);
  }
  EXPECT_GT(1 - m.eos.rho0 * pts.volume[0] / pts.mass[0], 0.05);  // compressed
  EXPECT_NEAR(law.internal_energy(0) / work, 1.0, 1e-12) << "Dim " << Dim << " Y " << Y;
}

TEST(MieGruneisen, InternalEnergyIsTheStressWork) {
  for (const double Y : {0.0, 0.12, 5.0}) {
    energy_is_the_work<1>(Y);
    energy_is_the_work<2>(Y);
    energy_is_the_work<3>(Y);
  }
}

TEST(MieGruneisen, InternalEnergyHoldsTheLinearViscositysWork) {
  energy_is_the_work<1>(0.12, 2.0);
  energy_is_the_work<2>(0.12, 2.0);
  energy_is_the_work<3>(0.0, 2.0);
}

TEST(MieGruneisen, CompressionPastOneOverSStopsTheRun) {
  const auto m = copper();
  for (int threads : {1, 2}) {
    PointSet<2> pts(4, m.eos.rho0);
    MieGruneisen<2> law(m);
    law.set_threads(threads);
    auto p = pts.view();
    law.initialize(p);
    Eigen::Matrix2d L;
    L << -1.0, 0.3, 0.2, 0.5;
    pts.set_grad_v(L);  // the others would change if they were updated
    pts.volume[2] *= 1 - 0.7;   // eta = 0.7 > 1 / s = 0.671
    pts.volume[3] *= 1 - 0.75;  // past it as well: the lowest is named
    try {
      law.update_stress(p, 1e-3);
      ADD_FAILURE() << "no RunError";
    } catch (const RunError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("point 2"), std::string::npos) << what;
      EXPECT_NE(what.find("eta = 1 - rho0 / rho = 0.7"), std::string::npos) << what;
      EXPECT_NE(what.find("rho / rho0 = 3.33333"), std::string::npos) << what;
    }
    // No point was updated: the state is the start's.
    for (std::size_t q = 0; q < 4; ++q) {
      EXPECT_EQ(law.internal_energy(q), 0.0) << q;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(pts.sig[k][q], 0.0) << q << " " << k;
    }
    MieGruneisen<2> fresh(m);
    EXPECT_THROW(fresh.initialize(p), RunError);
  }
}

// Each point's update is its own: one thread and three give the same bits, the viscous
// work included.
template <int Dim>
void same_bits_on_threads() {
  const auto m = copper();
  constexpr std::size_t n = 1000;
  std::array<PointSet<Dim>, 2> pts{PointSet<Dim>(n, m.eos.rho0), PointSet<Dim>(n, m.eos.rho0)};
  std::array<MieGruneisen<Dim>, 2> law{MieGruneisen<Dim>(m), MieGruneisen<Dim>(m)};
  std::array<std::array<std::vector<double>, Dim * Dim>, 2> qv;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n01;
  std::vector<double> L(n * Dim * Dim), shrink(n);
  for (double& x : L) x = 0.5 * n01(rng);
  for (double& x : shrink) x = 1.0 - 0.01 * std::abs(n01(rng));
  for (int k = 0; k < 2; ++k) {
    law[k].set_threads(k == 0 ? 1 : 3);
    auto p = pts[k].view();
    law[k].initialize(p);
    for (auto& c : qv[k]) c.assign(n, 0.0);
    for (int step = 0; step < 5; ++step) {
      for (std::size_t q = 0; q < n; ++q) {
        for (int c = 0; c < Dim * Dim; ++c) {
          pts[k].L[c][q] = L[q * Dim * Dim + c];
          qv[k][c][q] = -0.1 * std::abs(L[q * Dim * Dim + c]);
        }
        pts[k].volume[q] *= shrink[q];
      }
      law[k].update_stress(p, 1e-3);
      std::array<const double*, Dim * Dim> ptr;
      for (int c = 0; c < Dim * Dim; ++c) ptr[c] = qv[k][c].data();
      law[k].add_viscous_work(p, ptr, 1e-3);
    }
  }
  for (std::size_t q = 0; q < n; ++q) {
    EXPECT_EQ(law[0].internal_energy(q), law[1].internal_energy(q)) << q;
    for (int c = 0; c < Dim * Dim; ++c) EXPECT_EQ(pts[0].sig[c][q], pts[1].sig[c][q]) << q << " " << c;
  }
}

TEST(MieGruneisen, SameBitsOnOneThreadAndThree) {
  same_bits_on_threads<2>();
  same_bits_on_threads<3>();
}

TEST(MieGruneisen, SaveAndLoadContinueBitForBit) {
  const auto m = copper();
  PointSet<3> a(3, m.eos.rho0);
  MieGruneisen<3> law(m), copy(m);
  auto pa = a.view();
  law.initialize(pa);
  Matrix3d L;
  L << -0.5, 0.4, 0.0, -0.3, 0.1, 0.2, 0.0, 0.1, -0.2;
  a.set_grad_v(L);
  auto step = [&](PointSet<3>& s, MieGruneisen<3>& w) {
    for (std::size_t q = 0; q < s.n; ++q) s.volume[q] *= 1 + 1e-3 * L.trace();
    w.update_stress(s.view(), 1e-3);
  };
  for (int k = 0; k < 50; ++k) step(a, law);
  std::stringstream buf;
  law.save(buf);
  copy.load(buf);
  PointSet<3> b = a;
  for (int k = 0; k < 50; ++k) {
    step(a, law);
    step(b, copy);
  }
  for (std::size_t q = 0; q < 3; ++q) {
    EXPECT_EQ(a.stress(q), b.stress(q));
    EXPECT_EQ(law.internal_energy(q), copy.internal_energy(q));
    EXPECT_EQ(law.deviator(q), copy.deviator(q));
  }
  EXPECT_GT(law.internal_energy(0), 0.0);
  std::stringstream cut(buf.str().substr(0, 40));
  EXPECT_THROW(copy.load(cut), InputError);
}

TEST(MieGruneisen, ViscousWorkHeatsThePoint) {
  const auto m = copper(0.0);
  PointSet<2> pts(1, m.eos.rho0);
  MieGruneisen<2> law(m);
  auto p = pts.view();
  law.initialize(p);
  Eigen::Matrix2d L;
  L << -2.0, 0.0, 0.0, 0.0;
  pts.set_grad_v(L);
  const double dt = 1e-3;
  pts.volume[0] *= (1 - dt) / (1 + dt);
  law.update_stress(p, dt);
  const double e0 = law.internal_energy(0), p0 = law.pressure(0);
  std::array<std::vector<double>, 4> qv;
  for (auto& c : qv) c.assign(1, 0.0);
  qv[0][0] = -1.5;  // compressive viscous stress along x
  law.add_viscous_work(p, std::array<double*, 4>{qv[0].data(), qv[1].data(), qv[2].data(), qv[3].data()}, dt);
  const double de = dt * law.specific_volume(0) * (-1.5) * (-2.0);
  EXPECT_NEAR(law.internal_energy(0) - e0, de, 1e-15);
  EXPECT_NEAR(law.pressure(0) - p0, m.eos.gamma0 * m.eos.rho0 * de, 1e-13);
  EXPECT_NEAR(pts.stress(0)(0, 0), -law.pressure(0), 1e-13);
}

std::vector<std::string> read_errors(const std::string& table) {
  auto deck = io::Deck::from_string("[material]\nmodel = \"mie_gruneisen\"\n" + table);
  auto m = deck.root().table("material");
  m.string("model");
  MieGruneisenEntry::read(m, Context{2, "", "", {}});
  return deck.errors();
}

bool has(const std::vector<std::string>& errs, const std::string& what) {
  for (const auto& e : errs)
    if (e.find(what) != std::string::npos) return true;
  return false;
}

TEST(MieGruneisen, DeckTableIsChecked) {
  const std::string ok =
      "density = 8.93\nsound_speed = 3.94\nslope = 1.49\ngruneisen = 1.99\nshear_modulus = 45.0\n"
      "yield_stress = 0.12\n";
  auto deck = io::Deck::from_string("[material]\nmodel = \"mie_gruneisen\"\n" + ok);
  auto t = deck.root().table("material");
  const auto model = app::read_material(t, app::material_context(2, "", ""));
  ASSERT_TRUE(deck.errors().empty());
  ASSERT_TRUE(model);
  EXPECT_EQ(model->name(), "mie_gruneisen");
  EXPECT_EQ(model->density(), 8.93);
  EXPECT_NEAR(model->wave_speed(2, 8.93, 0.0), std::sqrt(3.94 * 3.94 + 4.0 / 3 * 45.0 / 8.93), 1e-12);
  EXPECT_TRUE(std::isnan(model->wave_speed(2, 8.93 / (1 - 0.7), 0.0)));
  EXPECT_EQ(make<1>(*model)->name(), "mie_gruneisen");

  auto e = read_errors("density = 8.93\nsound_speed = 3.94\nslope = -1.0\ngruneisen = 1.99\n"
                       "shear_modulus = 45.0\nyield_stress = 0.12\n");
  EXPECT_TRUE(has(e, "material.slope") && has(e, "must not be negative"));
  EXPECT_EQ(e.size(), 1u);
  e = read_errors("density = 8.93\nsound_speed = 0.0\nslope = 1.49\ngruneisen = 1.99\n"
                  "shear_modulus = 0.0\nyield_stress = 0.12\n");
  EXPECT_TRUE(has(e, "material.sound_speed") && has(e, "must be positive"));
  EXPECT_TRUE(has(e, "material.shear_modulus") && has(e, "yield_stress = 0 makes a fluid"));
  e = read_errors(
      "density = 8.93\nsound_speed = 3.94\nslope = 1.49\nshear_modulus = 45.0\nyield_stress = 0.0\n");
  EXPECT_TRUE(has(e, "material.gruneisen") && has(e, "missing"));
  EXPECT_EQ(e.size(), 1u);
  e = read_errors("density = 8.93\nsound_speed = 3.94\nslope = 1.49\ngruneisen = -0.5\n"
                  "shear_modulus = 45.0\nyield_stress = -1.0\n");
  EXPECT_TRUE(has(e, "material.gruneisen") && has(e, "material.yield_stress"));
}

}  // namespace
}  // namespace mpmx::material
