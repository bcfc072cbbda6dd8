// Every shape scheme: partition of unity, gradients that sum to zero (eq. 4.7 follows),
// the DDMP gradient's limits, and GIMP/CPDI against direct integration.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"
#include "mpmx/mpm/shape/hat.hpp"
#include "mpmx/mpm/shape/scheme.hpp"
#include "mpmx/mpm/transfer.hpp"

using namespace mpmx::mpm;

namespace {

Grid<1> grid() { return Grid<1>({-1.0}, {3.0}, {20}); }

// Particles spread over the whole grid, ends included, with domain lengths near dx/3.
Particles<1> spread_particles(const Grid<1>& g, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles<1> p;
  p.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    p.x[0][q] = g.lower[0] + (g.upper[0] - g.lower[0]) * u(rng);
    p.length[0][q] = g.dx[0] * (0.2 + 0.3 * u(rng));
    p.volume[q] = p.volume0[q] = p.length[0][q];
    p.mass[q] = p.volume[q];
    p.stress[0][q] = u(rng) - 0.5;
  }
  p.x[0][0] = g.lower[0];  // exactly on the ends
  p.x[0][1] = g.upper[0];
  return p;
}

class EveryScheme : public ::testing::TestWithParam<Scheme> {};

TEST_P(EveryScheme, PartitionOfUnityAndZeroGradientSum) {
  const Grid<1> g = grid();
  const Particles<1> p = spread_particles(g, 400, 7);
  ShapeEvaluator eval({GetParam(), 8}, g);
  Stencil<1> st;
  eval(g, p, st);
  st = shape::expanded(st, g);  // DDMP: the gradient in full
  for (std::size_t q = 0; q < p.size(); ++q) {
    double s = 0.0, gs = 0.0, gabs = 0.0;
    for (int k = 0; k < st.width; ++k) {
      s += st.S[q * st.width + k];
      gs += st.G[0][q * st.width + k];
      gabs += std::abs(st.G[0][q * st.width + k]);
    }
    EXPECT_NEAR(s, 1.0, 1e-13) << "particle " << q << " at " << p.x[0][q];
    EXPECT_NEAR(gs, 0.0, 1e-12 * (gabs + 1.0)) << "particle " << q;
  }
}

TEST_P(EveryScheme, InternalForcesSumToZero) {  // eq. 4.7
  const Grid<1> g0 = grid();
  Grid<1> g = g0;
  const Particles<1> p = spread_particles(g, 400, 11);
  ShapeEvaluator eval({GetParam(), 8}, g);
  Stencil<1> st;
  eval(g, p, st);
  p2g(p, st, false, g);
  double sum = 0.0, abs = 0.0;
  for (double f : g.force[0]) sum += f, abs += std::abs(f);
  EXPECT_GT(abs, 1.0);
  EXPECT_LT(std::abs(sum), 1e-14 * abs);
  double m = 0.0, mp = 0.0;
  for (double x : g.mass) m += x;
  for (double x : p.mass) mp += x;
  EXPECT_NEAR(m, mp, 1e-14 * mp);  // nodal mass equals particle mass
}

INSTANTIATE_TEST_SUITE_P(Shape, EveryScheme,
                         ::testing::Values(Scheme::mpm, Scheme::ugimp, Scheme::cpgimp, Scheme::cpdi,
                                           Scheme::ddmp, Scheme::ddmp_subpoints),
                         [](const auto& info) { return scheme_name(info.param); });

TEST(Ddmp, AlphaVanishesOnCellBoundariesAndIsHalfAtCentre) {  // eq. 3.27
  EXPECT_DOUBLE_EQ(shape::ddmp_alpha(0.0), 0.0);
  EXPECT_DOUBLE_EQ(shape::ddmp_alpha(1.0), 0.0);
  EXPECT_DOUBLE_EQ(shape::ddmp_alpha(0.5), 0.5);
}

TEST(Ddmp, GradientIsContinuousAcrossCellBoundaries) {  // the point of eq. 3.31
  const Grid<1> g = grid();
  shape::DdmpTable t(g);
  const double inv = g.inv_dx[0];
  for (int c = 1; c < g.cells[0]; ++c) {
    // Just left and just right of node c: all node weights must agree.
    double left[8] = {}, right[8] = {};
    shape::add_ddmp_gradient(g, t, c - 1e-9, 1.0, c - 3, left);
    shape::add_ddmp_gradient(g, t, c + 1e-9, 1.0, c - 3, right);
    for (int k = 0; k < 8; ++k) EXPECT_NEAR(left[k], right[k], 1e-6 * inv) << "node " << c;
  }
}

TEST(Ddmp, ReproducesLinearFieldGradientExactly) {
  // For v_i = a x_i the DDMP gradient gives a everywhere inside (central differences
  // and the hat gradient are exact for linear fields).
  const Grid<1> g = grid();
  shape::DdmpTable t(g);
  for (double xi = 0.01; xi < g.cells[0]; xi += 0.173) {
    double w[32] = {};
    const int first = static_cast<int>(xi) - 1;
    shape::add_ddmp_gradient(g, t, xi, 1.0, first, w);
    double grad = 0.0;
    for (int k = 0; k < 4; ++k) grad += w[k] * 2.5 * g.node_x(first + k);
    EXPECT_NEAR(grad, 2.5, 1e-12) << "xi = " << xi;
  }
}

TEST(Gimp, ShapeIsTheDomainAverageOfTheHat) {  // eq. 3.17
  const Grid<1> g = grid();
  Particles<1> p;
  p.resize(1);
  p.x[0][0] = 0.37;
  p.length[0][0] = 0.13;
  Stencil<1> st;
  ShapeEvaluator({Scheme::ugimp, 1}, g)(g, p, st);
  for (int k = 0; k < st.width; ++k) {
    const int i = st.node[k] - Grid<1>::ghost;
    // Midpoint rule with many points.
    double avg = 0.0;
    const int n = 20000;
    for (int s = 0; s < n; ++s) {
      const double x = 0.37 - 0.065 + 0.13 * (s + 0.5) / n;
      avg += shape::hat((x - g.lower[0]) * g.inv_dx[0] - i) / n;
    }
    EXPECT_NEAR(st.S[k], avg, 1e-9) << "node " << i;
  }
}

TEST(SubPoints, OneSubPointIsPlainDdmp) {
  const Grid<1> g = grid();
  const Particles<1> p = spread_particles(g, 50, 3);
  Stencil<1> a, b;
  ShapeEvaluator({Scheme::ddmp, 1}, g)(g, p, a);
  ShapeEvaluator({Scheme::ddmp_subpoints, 1}, g)(g, p, b);
  a = shape::expanded(a, g);
  b = shape::expanded(b, g);
  for (std::size_t q = 0; q < p.size(); ++q)
    for (int k = 0; k < a.width; ++k) {
      // Same nodes: compare by node index.
      const int node = a.node[q * a.width + k];
      double gb = 0.0;
      for (int j = 0; j < b.width; ++j)
        if (b.node[q * b.width + j] == node) gb += b.G[0][q * b.width + j];
      EXPECT_NEAR(a.G[0][q * a.width + k], gb, 1e-12);
    }
}

}  // namespace
