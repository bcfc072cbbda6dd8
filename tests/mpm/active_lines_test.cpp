// ctest-label: unit
// The 2-D/3-D step's grid passes visit only the node lines' active ranges
// (mpm/active_lines.hpp). A grid whose earlier step served points elsewhere must end
// p2g, the small-mass distribution, the solve and the gradient velocities with the same
// node arrays, maps and tallies, bit for bit, as a fresh grid whose passes after p2g
// cover every node: for every scheme, in 2-D and 3-D, points by the grid's faces
// included. (DDMP's operator inside p2g: tests/mpm/ddmp_operator_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>

#include "mpmx/mpm/active_lines.hpp"
#include "mpmx/mpm/mass_distribution.hpp"
#include "mpmx/mpm/shape/scheme.hpp"
#include "mpmx/mpm/solve.hpp"
#include "mpmx/mpm/transfer.hpp"
#include "shape_test_util.hpp"

using namespace mpmx::mpm;

namespace {

template <int Dim>
void expect_same_nodes(const Grid<Dim>& a, const Grid<Dim>& b) {
  EXPECT_EQ(a.mass, b.mass);
  for (int d = 0; d < Dim; ++d) {
    EXPECT_EQ(a.momentum[d], b.momentum[d]);
    EXPECT_EQ(a.force[d], b.force[d]);
  }
}

template <int Dim>
void compare_active_lines(Scheme scheme) {
  SCOPED_TRACE(scheme_name(scheme) + " in " + std::to_string(Dim) + "-D");
  const Grid<Dim> g0 = mpmx::test::uneven_grid<Dim>();
  // The earlier step's points anywhere; this step's fewer and in the middle along x, some
  // by the other faces.
  const Particles<Dim> before = mpmx::test::random_particles<Dim>(g0, 90, 3, 0.3);
  Particles<Dim> now = mpmx::test::random_particles<Dim>(g0, 40, 4, 0.3);
  const double length = g0.upper[0] - g0.lower[0];  // along x: the grid's middle only
  for (std::size_t q = 0; q < now.size(); ++q)
    now.x[0][q] = g0.lower[0] + length * (0.3 + 0.4 * (now.x[0][q] - g0.lower[0]) / length);
  SchemeOptions opt;
  opt.scheme = scheme;
  opt.subpoints = 2;
  opt.subpoints_axes = {2, 2, 2};
  ShapeEvaluator<Dim> eval(opt, g0);
  Stencil<Dim> st_before, st_now;
  eval(g0, before, st_before);
  eval(g0, now, st_now);
  Boundaries bc;
  bc.face[0].type = BoundarySide::Type::fixed;
  bc.face[2].type = bc.face[3].type = BoundarySide::Type::roller;

  Grid<Dim> used = g0, fresh = g0;
  Tallies t0;
  p2g(before, st_before, false, used, 2);
  solve_grid(used, bc, 0.0, 1e-3, t0, 2);
  p2g(now, st_now, false, used, 2);
  std::size_t active = 0, real = 1;
  for (std::size_t l = 0; l < g0.lines(); ++l)
    if (used.active_lo[l] <= used.active_hi[l]) active += static_cast<std::size_t>(used.active_hi[l] - used.active_lo[l] + 1);
  for (int d = 0; d < Dim; ++d) real *= static_cast<std::size_t>(g0.cells[d] + 1);
  ASSERT_LT(active, real);  // the passes do skip nodes
  p2g(now, st_now, false, fresh, 2);
  expect_same_nodes(used, fresh);
  // From here the fresh grid's passes cover every node: the reference.
  std::fill(fresh.active_lo.begin(), fresh.active_lo.end(), 0);
  std::fill(fresh.active_hi.begin(), fresh.active_hi.end(), g0.cells[0]);
  fresh.span_lo = fresh.active_lo;
  fresh.span_hi = fresh.active_hi;

  SmallMassMaps mu, mf;
  const double m_eps = 0.04 * now.mass[0];
  distribute_small_mass_forces(used, m_eps, mu, 2);
  distribute_small_mass_forces(fresh, m_eps, mf, 2);
  expect_same_nodes(used, fresh);
  EXPECT_EQ(mu.c0.node, mf.c0.node);
  EXPECT_EQ(mu.c1.node, mf.c1.node);
  EXPECT_FALSE(mu.c0.node.empty());

  Tallies tu, tf;
  solve_grid(used, bc, 0.0, 1e-3, tu, 2);
  solve_grid(fresh, bc, 0.0, 1e-3, tf, 2);
  for (int d = 0; d < Dim; ++d) {  // nodes the earlier points left have v = 0 again
    EXPECT_EQ(used.velocity[d], fresh.velocity[d]);
    EXPECT_EQ(used.velocity_L[d], fresh.velocity_L[d]);
  }
  EXPECT_EQ(tu.node_mass, tf.node_mass);
  EXPECT_EQ(tu.boundary_impulse, tf.boundary_impulse);
  EXPECT_EQ(tu.boundary_work, tf.boundary_work);
  EXPECT_EQ(tu.max_force_sum, tf.max_force_sum);

  gradient_velocities(used, mu, midpoint_weights(true), 2);
  gradient_velocities(fresh, mf, midpoint_weights(true), 2);
  for (std::size_t i = 0; i < g0.storage; ++i) {
    if (!(fresh.mass[i] > 0.0)) continue;
    for (int d = 0; d < Dim; ++d) EXPECT_EQ(used.gradient_velocity[d][i], fresh.gradient_velocity[d][i]) << i;
  }
}

}  // namespace

TEST(ActiveLines, AGridThatServedOtherPointsGivesTheFreshGridsBitsIn2D) {
  for (const std::string& name : scheme_names()) compare_active_lines<2>(scheme_from_name(name));
}
TEST(ActiveLines, AGridThatServedOtherPointsGivesTheFreshGridsBitsIn3D) {
  for (const std::string& name : scheme_names()) compare_active_lines<3>(scheme_from_name(name));
}
