// ctest-label: unit
// The step a state allows (mpm/step_limit.hpp): the Courant step from each point's wave
// speed and speed; the viscosity's explicit limit h / (Q + sqrt(Q^2 + c^2)) where a point
// is compressed; the volume-strain bound; the same step and limiting point for any thread
// count.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/mpm_test_util.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/points.hpp"
#include "mpmx/mpm/step_limit.hpp"

using namespace mpmx;

namespace {

// N6's copper plate impact (Mie-Gruneisen, tensor viscosity) with dt = "cfl".
app::MpmConfig impact() {
  return test::deck_with(test::example("N6_copper_planar_impact.toml"), [](toml::table& t) {
    auto& time = *t["time"].as_table();
    time.insert_or_assign("dt", "cfl");
    time.insert_or_assign("cfl", 0.5);
  });
}

}  // namespace

TEST(StepLimit, CourantViscosityAndVolumeStrainEachWhereTheyBind) {
  const auto c = impact();
  auto s = app::make_state<2>(c, true, 1);
  ASSERT_TRUE(s.tensor_viscosity.on);
  const auto view = mpm::points(s.particles);
  double h = std::min(s.grid.dx[0], s.grid.dx[1]), fastest = 0;
  for (std::size_t q = 0; q < s.particles.size(); ++q)
    fastest = std::max(fastest, s.material->signal_speed(view, q) + std::hypot(s.particles.v[0][q], s.particles.v[1][q]));
  // At rest (no gradient yet): the Courant step.
  mpm::StepLimit l = mpm::step_limit(s, {0.5, 0.02});
  EXPECT_EQ(l.by, mpm::StepLimiter::cfl);
  EXPECT_DOUBLE_EQ(l.dt, 0.5 * h / fastest);
  // One point compressed uniaxially at rate r: its viscous speed Q = l (c_L a + c_q l r) / h.
  const std::size_t q = s.particles.size() / 2;
  const double r = 50.0 * fastest / h;  // steep enough to bind
  s.particles.grad_v[0][q] = -r;
  l = mpm::step_limit(s, {0.5, 1.0});
  ASSERT_EQ(l.by, mpm::StepLimiter::viscosity);
  EXPECT_EQ(l.point, static_cast<std::int64_t>(q));
  const double a = s.material->sound_speed(view, q), len = 0.5 * (view.length[0][q] + view.length[1][q]);
  const double Q = len * (1.5 * a + 2.0 * len * r) / h, c_q = s.material->signal_speed(view, q);
  const double v = std::hypot(s.particles.v[0][q], s.particles.v[1][q]);
  EXPECT_NEAR(l.dt, 0.5 * h / (v + Q + std::sqrt(Q * Q + c_q * c_q)), 1e-12 * l.dt);
  // The same gradient under a tight volume-strain bound: |tr L| dt = the bound.
  l = mpm::step_limit(s, {0.5, 1e-6});
  EXPECT_EQ(l.by, mpm::StepLimiter::volume_strain);
  EXPECT_NEAR(l.dt, 1e-6 / r, 1e-15);
}

TEST(StepLimit, SameStepAndPointOnAnyThreadCount) {
  const auto c = impact();
  auto s = app::make_state<2>(c, true, 1);
  // Two points tied for the largest compression: the first wins on every thread count.
  const std::size_t n = s.particles.size();
  for (std::size_t q : {n / 3, 2 * n / 3}) s.particles.grad_v[0][q] = -1e3;
  for (std::size_t q = 0; q < n; q += 7) s.particles.grad_v[3][q] = -1.0 * (q % 5);
  const mpm::StepLimit one = mpm::step_limit(s, {0.5, 1e-3});
  for (int threads : {2, 3, 4}) {
    s.threads = threads;
    for (const double strain : {1e-3, 1.0}) {
      s.threads = 1;
      const mpm::StepLimit ref = mpm::step_limit(s, {0.5, strain});
      s.threads = threads;
      const mpm::StepLimit l = mpm::step_limit(s, {0.5, strain});
      EXPECT_EQ(l.dt, ref.dt) << threads;
      EXPECT_EQ(l.point, ref.point) << threads;
      EXPECT_EQ(l.point, static_cast<std::int64_t>(n / 3)) << threads;
    }
  }
  EXPECT_EQ(one.by, mpm::StepLimiter::volume_strain);
}
