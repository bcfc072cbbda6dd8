// Driven and reflected wave (ADMPM eqs. 8.21, 8.22, 8.26, 8.27): values, boundary
// conditions, the equations of motion by finite differences, and the total energy
// against a numerical integral of eq. 8.26.
// ctest-label: unit
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mpmx/core/error.hpp"
#include "mpmx/reference/wave_reflection.hpp"

using mpmx::InputError;
using mpmx::reference::WaveReflection;
namespace ref = mpmx::reference;

namespace {

// 1/2 int_0^L (rho0 v^2 + Y eps^2) dx (eq. 8.26) by 10-point Gauss-Legendre on 400
// panels per smooth piece, the pieces split at the two fronts x = L - ct, x = ct - L.
double energy_integral(const WaveReflection& w, double t) {
  static constexpr std::array<double, 5> xg{0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                            0.8650633666889845, 0.9739065285171717};
  static constexpr std::array<double, 5> wg{0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                            0.1494513499390986, 0.0666713443573362};
  const double Y = w.rho0 * w.c * w.c;
  auto e = [&](double x) {
    const double v = ref::velocity(w, x, t), s = ref::strain(w, x, t);
    return 0.5 * (w.rho0 * v * v + Y * s * s);
  };
  std::vector<double> cuts{0.0, w.L};
  for (double f : {w.L - w.c * t, w.c * t - w.L})
    if (f > 0.0 && f < w.L) cuts.push_back(f);
  std::sort(cuts.begin(), cuts.end());
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const int panels = 400;
    const double h = (cuts[k + 1] - cuts[k]) / panels;
    for (int p = 0; p < panels; ++p) {
      const double mid = cuts[k] + (p + 0.5) * h;
      for (std::size_t g = 0; g < xg.size(); ++g)
        sum += 0.5 * h * wg[g] * (e(mid - 0.5 * h * xg[g]) + e(mid + 0.5 * h * xg[g]));
    }
  }
  return sum;
}

// Eq. 8.27 exactly as printed in ADMPM (second branch for t > L/c).
double printed_eq_827(const WaveReflection& w, double t) {
  const double base = w.rho0 * w.v0 * w.v0 * w.c, om = w.omega, T = w.L / w.c;
  if (t <= T) return base * (t / 2 - std::sin(2 * om * t) / (4 * om));
  return base * (t / 2 - std::sin(om * (t - 2 * T)) * std::cos(om * (3 * t - 2 * T)) / (2 * om) -
                 std::sin(4 * om * (t - T)) / (8 * om));
}

}  // namespace

TEST(WaveReflection, ValuesMatchIndependentlyComputedNumbers) {
  // Python, straight from the printed eqs. 8.21/8.22 with L = c = 1, v0 = 0.01, omega = 10.
  const WaveReflection w{};
  EXPECT_NEAR(ref::velocity(w, 0.9, 0.5), -0.007568024953079283, 1e-16);
  EXPECT_NEAR(ref::strain(w, 0.9, 0.5), -0.007568024953079283, 1e-16);
  EXPECT_EQ(ref::velocity(w, 0.3, 0.5), 0.0);  // ahead of the incoming front
  EXPECT_EQ(ref::strain(w, 0.3, 0.5), 0.0);
  EXPECT_NEAR(ref::velocity(w, 0.1, 1.4), -0.01100044282723007, 1e-16);  // both waves
  EXPECT_NEAR(ref::strain(w, 0.1, 1.4), -0.008178042666032708, 1e-16);
  EXPECT_NEAR(ref::velocity(w, 0.8, 1.4), -0.00536572918000435, 1e-16);
  EXPECT_NEAR(ref::strain(w, 0.8, 1.4), -0.00536572918000435, 1e-16);
  EXPECT_NEAR(ref::density(w, 0.1, 1.4), 1.0 + 0.008178042666032708, 1e-15);
  EXPECT_NEAR(ref::stress(w, 0.1, 1.4), -0.008178042666032708, 1e-16);
}

TEST(WaveReflection, BoundaryConditionsAndContinuityAtFronts) {
  const WaveReflection w{1.0, 2.0, 0.02, 7.0, 1.3};
  for (double t : {0.1, 0.45, 0.6, 0.99}) {
    EXPECT_NEAR(ref::velocity(w, 0.0, t), 0.0, 1e-17);                             // eq. 8.12a
    EXPECT_NEAR(ref::velocity(w, w.L, t), w.v0 * std::sin(w.omega * t), 1e-15);  // eq. 8.12b
    for (double front : {w.L - w.c * t, w.c * t - w.L}) {
      if (front <= 0.0 || front >= w.L) continue;
      EXPECT_NEAR(ref::velocity(w, front - 1e-9, t), ref::velocity(w, front + 1e-9, t), 1e-9);
      EXPECT_NEAR(ref::strain(w, front - 1e-9, t), ref::strain(w, front + 1e-9, t), 1e-9);
    }
  }
}

TEST(WaveReflection, StrainSignsSatisfyMomentumEquation) {
  // rho0 v_t = Y eps_x and eps_t = v_x, by centred differences, in every region; the
  // left-moving wave needs eps = +v/c for this (eq. 8.22 as printed).
  const WaveReflection w{1.0, 1.0, 0.01, 10.0, 1.0};
  const double Y = w.rho0 * w.c * w.c, h = 1e-6;
  struct P {
    double x, t;
  };
  for (P p : {P{0.9, 0.5}, P{0.7, 0.8}, P{0.2, 1.5}, P{0.05, 1.9}, P{0.85, 1.4}, P{0.95, 1.1}}) {
    const double v_t = (ref::velocity(w, p.x, p.t + h) - ref::velocity(w, p.x, p.t - h)) / (2 * h);
    const double v_x = (ref::velocity(w, p.x + h, p.t) - ref::velocity(w, p.x - h, p.t)) / (2 * h);
    const double e_t = (ref::strain(w, p.x, p.t + h) - ref::strain(w, p.x, p.t - h)) / (2 * h);
    const double e_x = (ref::strain(w, p.x + h, p.t) - ref::strain(w, p.x - h, p.t)) / (2 * h);
    EXPECT_NEAR(w.rho0 * v_t, Y * e_x, 1e-7) << "x=" << p.x << " t=" << p.t;
    EXPECT_NEAR(e_t, v_x, 1e-7) << "x=" << p.x << " t=" << p.t;
    EXPECT_GT(std::abs(v_t), 1e-3);  // the check is not vacuous
  }
  // A wave moving in -x: strain = +v/c, not -v/c.
  EXPECT_GT(ref::strain(w, 0.95, 0.1) * ref::velocity(w, 0.95, 0.1), 0.0);
}

TEST(WaveReflection, TotalEnergyMatchesIntegralOfEq826) {
  for (const WaveReflection& w : {WaveReflection{}, WaveReflection{1.0, 1.0, 0.01, 7.3, 1.0},
                                  WaveReflection{2.0, 3.0, 0.05, 4.0, 2.5}}) {
    const double T = 2.0 * w.L / w.c;
    for (double f : {0.0, 0.1, 0.3, 0.5, 0.62, 0.75, 0.9, 1.0}) {
      const double t = f * T;
      const double integral = energy_integral(w, t);
      EXPECT_NEAR(ref::total_energy(w, t), integral, 1e-12 * (1.0 + integral) + 1e-9 * integral) << "t=" << t;
    }
  }
}

TEST(WaveReflection, PrintedEq827SecondBranchDisagreesWithTheIntegral) {
  // Documents the finding: the ADMPM formula jumps at t = L/c and misses eq. 8.26.
  const WaveReflection w{};  // the ADMPM case
  const double T = w.L / w.c;
  const double jump = printed_eq_827(w, T + 1e-12) - printed_eq_827(w, T);
  EXPECT_NEAR(jump, w.rho0 * w.v0 * w.v0 * w.c * std::sin(2 * w.omega * T) / (2 * w.omega), 1e-12);
  const double t = 1.5;
  EXPECT_GT(std::abs(printed_eq_827(w, t) - energy_integral(w, t)), 1e-3 * energy_integral(w, t));
  EXPECT_NEAR(printed_eq_827(w, 0.7), energy_integral(w, 0.7), 1e-12);  // first branch is right
}

TEST(WaveReflection, RejectsTimesOutsideValidityAndBadParameters) {
  const WaveReflection w{};
  EXPECT_DOUBLE_EQ(ref::end_time(w), 2.0);
  EXPECT_NO_THROW(ref::velocity(w, 0.5, 2.0));
  EXPECT_NO_THROW(ref::velocity(w, 0.5, 2.0 + 1e-14));
  EXPECT_THROW(ref::velocity(w, 0.5, 2.01), InputError);
  EXPECT_THROW(ref::strain(w, 0.5, -0.1), InputError);
  EXPECT_THROW(ref::total_energy(w, 2.5), InputError);
  EXPECT_THROW(ref::velocity(WaveReflection{1.0, 0.0, 0.01, 10.0, 1.0}, 0.5, 0.1), InputError);
  EXPECT_THROW(ref::velocity(WaveReflection{-1.0, 1.0, 0.01, 10.0, 1.0}, 0.5, 0.1), InputError);
  EXPECT_THROW(ref::velocity(WaveReflection{1.0, 1.0, 0.01, -10.0, 1.0}, 0.5, 0.1), InputError);
}
