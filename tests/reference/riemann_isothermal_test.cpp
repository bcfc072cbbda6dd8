// Exact isothermal Riemann solver (dissertation ch. 4 shock tube): star states against
// values found independently (Python bisection on the wave curves, closed forms),
// Rankine-Hugoniot balances, fan continuity, conservation, acoustic limit.
// ctest-label: unit
#include <gtest/gtest.h>

#include <cmath>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/riemann_isothermal.hpp"

using mpmx::InputError;
using mpmx::reference::IsothermalRiemann;
using mpmx::reference::IsothermalStar;
using mpmx::reference::WaveKind;
namespace ref = mpmx::reference;

namespace {

// Mass and momentum flux jumps across a shock of speed s between states a and b.
void expect_rankine_hugoniot(double c, double rho_a, double u_a, double rho_b, double u_b, double s) {
  const double mass_a = rho_a * (u_a - s), mass_b = rho_b * (u_b - s);
  const double mom_a = rho_a * u_a * (u_a - s) + c * c * rho_a;
  const double mom_b = rho_b * u_b * (u_b - s) + c * c * rho_b;
  EXPECT_NEAR(mass_a, mass_b, 1e-12);
  EXPECT_NEAR(mom_a, mom_b, 1e-12);
  // s equals the Rankine-Hugoniot quotient quoted in the header.
  EXPECT_NEAR(s, (rho_b * u_b - rho_a * u_a) / (rho_b - rho_a), 1e-9 * std::abs(s));
}

IsothermalRiemann tube(double rho_l, double rho_r) { return IsothermalRiemann{{rho_l, 0.0}, {rho_r, 0.0}, 1.0, 0.5}; }

}  // namespace

TEST(RiemannIsothermal, StrongCaseMatchesBisection) {
  const IsothermalRiemann r = tube(4.0, 1.0);  // p_L / p_R = 4
  const IsothermalStar s = ref::solve_star(r);
  EXPECT_NEAR(s.rho, 1.9864932204910906, 1e-13);
  EXPECT_NEAR(s.u, 0.6999234776439902, 1e-13);
  EXPECT_NEAR(s.p, s.rho, 1e-15);
  EXPECT_EQ(s.left.kind, WaveKind::rarefaction);
  EXPECT_EQ(s.right.kind, WaveKind::shock);
  // Rankine-Hugoniot by hand from the bisection values: rho* u* / (rho* - 1).
  EXPECT_NEAR(s.right.head, 1.9864932204910906 * 0.6999234776439902 / 0.9864932204910906, 1e-12);
  EXPECT_NEAR(s.left.head, -1.0, 1e-15);
  EXPECT_NEAR(s.left.tail, s.u - 1.0, 1e-15);
  expect_rankine_hugoniot(r.c, s.rho, s.u, r.right.rho, r.right.u, s.right.head);
}

TEST(RiemannIsothermal, WeakCaseApproachesAcousticTheory) {
  const IsothermalRiemann r = tube(1.01, 1.0);
  const IsothermalStar s = ref::solve_star(r);
  EXPECT_NEAR(s.rho, 1.0049875595337414, 1e-14);
  EXPECT_NEAR(s.u, 0.004975167992135773, 1e-15);
  expect_rankine_hugoniot(r.c, s.rho, s.u, r.right.rho, r.right.u, s.right.head);
  // Acoustic: u* = c (p_L - p_R) / (2 p), p the mean pressure; the shock moves at ~c.
  const auto acoustic_error = [](double ratio) {
    const IsothermalStar w = ref::solve_star(tube(ratio, 1.0));
    const double u_ac = (ratio - 1.0) / (2.0 * 0.5 * (ratio + 1.0));
    return std::abs(w.u - u_ac) / u_ac;
  };
  EXPECT_LT(acoustic_error(1.01), 2e-5);
  // The relative deviation is second order in the pressure jump.
  EXPECT_NEAR(acoustic_error(1.01) / acoustic_error(1.001), 100.0, 5.0);
  EXPECT_NEAR(s.right.head, 1.0, 3e-3);
  EXPECT_NEAR(s.left.head, -1.0, 1e-15);
}

TEST(RiemannIsothermal, AllFourWaveCombinations) {
  // Two shocks (colliding streams): u* = 0, (rho - 1)/sqrt(rho) = 1, rho* = golden ratio^2.
  {
    const IsothermalRiemann r{{1.0, 1.0}, {1.0, -1.0}, 1.0, 0.0};
    const IsothermalStar s = ref::solve_star(r);
    EXPECT_NEAR(s.rho, (3.0 + std::sqrt(5.0)) / 2.0, 1e-14);
    EXPECT_NEAR(s.u, 0.0, 1e-15);
    EXPECT_EQ(s.left.kind, WaveKind::shock);
    EXPECT_EQ(s.right.kind, WaveKind::shock);
    expect_rankine_hugoniot(r.c, r.left.rho, r.left.u, s.rho, s.u, s.left.head);
    expect_rankine_hugoniot(r.c, s.rho, s.u, r.right.rho, r.right.u, s.right.head);
  }
  // Two rarefactions (separating streams): u* = 0, ln rho* = -1.
  {
    const IsothermalRiemann r{{1.0, -1.0}, {1.0, 1.0}, 1.0, 0.0};
    const IsothermalStar s = ref::solve_star(r);
    EXPECT_NEAR(s.rho, std::exp(-1.0), 1e-15);
    EXPECT_NEAR(s.u, 0.0, 1e-15);
    EXPECT_EQ(s.left.kind, WaveKind::rarefaction);
    EXPECT_EQ(s.right.kind, WaveKind::rarefaction);
  }
  // Left shock, right rarefaction: the mirror image of the strong case.
  {
    const IsothermalStar s = ref::solve_star(tube(1.0, 4.0));
    EXPECT_NEAR(s.rho, 1.9864932204910906, 1e-13);
    EXPECT_NEAR(s.u, -0.6999234776439902, 1e-13);
    EXPECT_EQ(s.left.kind, WaveKind::shock);
    EXPECT_EQ(s.right.kind, WaveKind::rarefaction);
    const ref::IsothermalSample a = ref::sample(tube(1.0, 4.0), 0.5 - 0.3, 0.2);
    const ref::IsothermalSample b = ref::sample(tube(4.0, 1.0), 0.5 + 0.3, 0.2);
    EXPECT_NEAR(a.rho, b.rho, 1e-14);
    EXPECT_NEAR(a.u, -b.u, 1e-14);
  }
  // Galilean invariance with a non-unit sound speed.
  {
    const IsothermalStar a = ref::solve_star(IsothermalRiemann{{3.0, 0.2}, {1.5, -0.4}, 2.0, 0.0});
    const IsothermalStar b = ref::solve_star(IsothermalRiemann{{3.0, 5.2}, {1.5, 4.6}, 2.0, 0.0});
    EXPECT_NEAR(a.rho, b.rho, 1e-13);
    EXPECT_NEAR(b.u - a.u, 5.0, 1e-13);
    EXPECT_NEAR(a.p, 4.0 * a.rho, 1e-13);
  }
}

TEST(RiemannIsothermal, FanIsContinuousAndSelfSimilar) {
  const IsothermalRiemann r = tube(4.0, 1.0);
  const IsothermalStar s = ref::solve_star(r);
  const double t = 0.15, eps = 1e-12;
  const double head = r.x0 + s.left.head * t, tail = r.x0 + s.left.tail * t;
  const auto in_head = ref::sample(r, s, head + eps, t), out_head = ref::sample(r, s, head - eps, t);
  const auto in_tail = ref::sample(r, s, tail - eps, t), out_tail = ref::sample(r, s, tail + eps, t);
  EXPECT_NEAR(in_head.rho, out_head.rho, 1e-10);
  EXPECT_NEAR(in_head.u, out_head.u, 1e-10);
  EXPECT_NEAR(in_tail.rho, out_tail.rho, 1e-10);
  EXPECT_NEAR(in_tail.u, out_tail.u, 1e-10);
  EXPECT_NEAR(out_tail.rho, s.rho, 1e-15);
  // Inside the fan: u = (x - x0)/t + c, rho = rho_L exp(-(u - u_L)/c).
  const double x = 0.5 * (head + tail);
  const auto m = ref::sample(r, s, x, t);
  EXPECT_NEAR(m.u, (x - r.x0) / t + 1.0, 1e-14);
  EXPECT_NEAR(m.rho, 4.0 * std::exp(-m.u), 1e-14);
  const auto m2 = ref::sample(r, s, r.x0 + 2.0 * (x - r.x0), 2.0 * t);
  EXPECT_NEAR(m2.rho, m.rho, 1e-14);
  // Shock: star behind, right state ahead.
  const double xs = r.x0 + s.right.head * t;
  EXPECT_NEAR(ref::sample(r, s, xs - eps, t).rho, s.rho, 1e-15);
  EXPECT_NEAR(ref::sample(r, s, xs + eps, t).rho, 1.0, 1e-15);
  // t = 0: the initial data.
  EXPECT_EQ(ref::sample(r, s, 0.49, 0.0).rho, 4.0);
  EXPECT_EQ(ref::sample(r, s, 0.51, 0.0).rho, 1.0);
}

TEST(RiemannIsothermal, ConservesMassAndMomentum) {
  // On [x0 - 1, x0 + 1] at rest: mass constant, momentum grows at p_L - p_R.
  const IsothermalRiemann r = tube(4.0, 1.0);
  const IsothermalStar s = ref::solve_star(r);
  const double t = 0.3;
  const int n = 200000;
  const double a = r.x0 - 1.0, h = 2.0 / n;
  double mass = 0.0, momentum = 0.0;
  for (int i = 0; i < n; ++i) {
    const auto q = ref::sample(r, s, a + (i + 0.5) * h, t);
    mass += q.rho * h;
    momentum += q.rho * q.u * h;
  }
  EXPECT_NEAR(mass, 4.0 + 1.0, 1e-4);
  EXPECT_NEAR(momentum, t * (4.0 - 1.0), 1e-4);
}

TEST(RiemannIsothermal, RejectsImpossibleParameters) {
  EXPECT_THROW(ref::solve_star(IsothermalRiemann{{0.0, 0.0}, {1.0, 0.0}, 1.0, 0.0}), InputError);
  EXPECT_THROW(ref::solve_star(IsothermalRiemann{{1.0, 0.0}, {-1.0, 0.0}, 1.0, 0.0}), InputError);
  EXPECT_THROW(ref::solve_star(IsothermalRiemann{{1.0, 0.0}, {1.0, 0.0}, 0.0, 0.0}), InputError);
  EXPECT_THROW(ref::sample(IsothermalRiemann{{1.0, NAN}, {1.0, 0.0}, 1.0, 0.0}, 0.0, 1.0), InputError);
}
