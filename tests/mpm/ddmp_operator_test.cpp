// ctest-label: unit
// DDMP's gradient factored into a sharp part on the hat's nodes and the grid's smoothing
// operator (shape/ddmp_operator.hpp) gives the same internal forces and velocity
// gradients as the gradient written out in full on the wide stencil, in 1-D, 2-D and 3-D,
// for points anywhere on the grid (ends and a cell past them included), with and without
// sub-points; and the same bits on one thread and two.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpmx/mpm/shape/ddmp_operator.hpp"
#include "mpmx/mpm/shape/scheme.hpp"
#include "mpmx/mpm/transfer.hpp"
#include "shape_test_util.hpp"

using namespace mpmx::mpm;

namespace {

template <int Dim>
void random_velocities(Grid<Dim>& g, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int a = 0; a < Dim; ++a) {
    for (double& v : g.velocity[a]) v = u(rng);
    for (double& v : g.velocity_L[a]) v = u(rng);
  }
}

double scale(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s = std::max(s, std::abs(x));
  return s;
}

template <int Dim>
void compare_factored(Scheme scheme) {
  SCOPED_TRACE(scheme_name(scheme) + " in " + std::to_string(Dim) + "-D");
  const Grid<Dim> g0 = mpmx::test::uneven_grid<Dim>();
  const Particles<Dim> p0 = mpmx::test::random_particles<Dim>(g0, 150, 5, -0.5);
  SchemeOptions opt;
  opt.scheme = scheme;
  opt.subpoints = 3;
  opt.subpoints_axes = {2, 3, 2};
  ShapeEvaluator<Dim> eval(opt, g0);
  Stencil<Dim> factored;
  eval(g0, p0, factored);
  ASSERT_TRUE(factored.smoothed());
  const Stencil<Dim> full = shape::expanded(factored, g0);
  ASSERT_FALSE(full.smoothed());

  // Internal forces (and the nodal mass and momentum, summed in another order: the
  // scatter runs in slabs as wide as the box).
  Grid<Dim> a = g0, b = g0, c = g0;
  p2g(p0, factored, false, a, 1);
  p2g(p0, full, false, b, 1);
  p2g(p0, factored, false, c, 2);
  for (int d = 0; d < Dim; ++d) {
    const double f = scale(b.force[d]);
    ASSERT_GT(f, 0.1 * scale(p0.volume) * g0.inv_dx[d]);  // forces of a point's size, not round-off
    for (std::size_t i = 0; i < g0.storage; ++i) {
      EXPECT_NEAR(a.force[d][i], b.force[d][i], 1e-13 * f) << "node " << i;
      EXPECT_EQ(a.force[d][i], c.force[d][i]) << "node " << i;
      EXPECT_NEAR(a.momentum[d][i], b.momentum[d][i], 1e-14 * scale(b.momentum[d]));
    }
  }
  for (std::size_t i = 0; i < g0.storage; ++i) EXPECT_NEAR(a.mass[i], b.mass[i], 1e-14 * scale(b.mass));
  // The scratch is back to zero for the next step.
  for (const auto& t : a.smooth_stress)
    for (double x : t) ASSERT_EQ(x, 0.0);

  // Velocity gradients at the midpoint velocities, and from v^L alone.
  for (const bool midpoint : {true, false}) {
    random_velocities(a, 9);
    random_velocities(b, 9);
    random_velocities(c, 9);
    Particles<Dim> pa = p0, pb = p0, pc = p0;
    g2p(a, factored, 1e-3, true, midpoint, pa, 1);
    g2p(b, full, 1e-3, true, midpoint, pb, 1);
    g2p(c, factored, 1e-3, true, midpoint, pc, 2);
    for (int k = 0; k < Dim * Dim; ++k) {
      const double s = scale(pb.grad_v[k]);
      ASSERT_GT(s, 0.1);
      for (std::size_t q = 0; q < p0.size(); ++q) {
        EXPECT_NEAR(pa.grad_v[k][q], pb.grad_v[k][q], 1e-13 * s) << "point " << q;
        EXPECT_EQ(pa.grad_v[k][q], pc.grad_v[k][q]) << "point " << q;
      }
    }
    for (int d = 0; d < Dim; ++d)
      for (std::size_t q = 0; q < p0.size(); ++q) {
        EXPECT_EQ(pa.v[d][q], pb.v[d][q]);
        EXPECT_EQ(pa.x[d][q], pb.x[d][q]);
      }
  }
}

}  // namespace

TEST(DdmpOperator, FactoredEqualsFullIn1D) {
  compare_factored<1>(Scheme::ddmp);
  compare_factored<1>(Scheme::ddmp_subpoints);
}
TEST(DdmpOperator, FactoredEqualsFullIn2D) {
  compare_factored<2>(Scheme::ddmp);
  compare_factored<2>(Scheme::ddmp_subpoints);
}
TEST(DdmpOperator, FactoredEqualsFullIn3D) {
  compare_factored<3>(Scheme::ddmp);
  compare_factored<3>(Scheme::ddmp_subpoints);
}

// The factored stencil holds the hat's 2^d nodes per point (the full one 4^d).
TEST(DdmpOperator, PointsSeeOnlyTheHatsNodes) {
  const Grid<3> g = mpmx::test::uneven_grid<3>();
  const Particles<3> p = mpmx::test::random_particles<3>(g, 40, 2, -0.5);
  Stencil<3> st;
  ShapeEvaluator<3>({Scheme::ddmp}, g)(g, p, st);
  EXPECT_EQ(st.width, 8);
  EXPECT_EQ(shape::expanded(st, g).width, 64);
}
