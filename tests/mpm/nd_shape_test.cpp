// ctest-label: unit
// Every scheme in 2-D and 3-D on grids of unequal cell sides: partition of unity,
// modified gradients that sum to zero (so internal forces balance, eq. 4.7), linear
// fields reproduced with their exact gradient; eq. 7.2 with alpha of eq. 7.3 is eq. 3.31
// with eq. 3.27 in 1-D; the tensor-product DDMP reduces to the 1-D scheme across y.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/mpm/shape/axis.hpp"
#include "mpmx/mpm/shape/ddmp.hpp"
#include "mpmx/mpm/shape/ddmp_operator.hpp"
#include "mpmx/mpm/shape/scheme.hpp"
#include "shape_test_util.hpp"

using namespace mpmx::mpm;

namespace {

struct Case {
  Scheme scheme;
  DdmpAlpha alpha;
};

class EverySchemeND : public ::testing::TestWithParam<Case> {};

template <int Dim>
void check_consistency(const Case& c) {
  const Grid<Dim> g = mpmx::test::uneven_grid<Dim>();
  const Particles<Dim> p = mpmx::test::random_particles<Dim>(g, 60, 11, 2.0);
  SchemeOptions opt;
  opt.scheme = c.scheme;
  opt.alpha = c.alpha;
  opt.subpoints_axes = {2, 3, 2};
  ShapeEvaluator<Dim> eval(opt, g);
  Stencil<Dim> st;
  eval(g, p, st);
  st = shape::expanded(st, g);  // DDMP: the gradient in full
  for (std::size_t q = 0; q < p.size(); ++q) {
    double s = 0.0, gsum[Dim] = {}, gabs = 0.0, xs[Dim] = {}, xg[Dim][Dim] = {};
    for (int k = 0; k < st.width; ++k) {
      const std::size_t e = q * st.width + k;
      // Grid indices of the entry's node from its storage index.
      std::size_t r = static_cast<std::size_t>(st.node[e]);
      double xi[Dim];
      for (int a = Dim - 1; a >= 0; --a) {
        const std::size_t i = r / g.stride[a];
        r %= g.stride[a];
        xi[a] = g.node_x(static_cast<int>(i) - Grid<Dim>::ghost, a);
      }
      s += st.S[e];
      for (int a = 0; a < Dim; ++a) {
        xs[a] += st.S[e] * xi[a];
        gsum[a] += st.G[a][e];
        gabs += std::abs(st.G[a][e]);
        for (int b = 0; b < Dim; ++b) xg[a][b] += xi[a] * st.G[b][e];
      }
    }
    EXPECT_NEAR(s, 1.0, 1e-13) << "particle " << q;
    for (int a = 0; a < Dim; ++a) {
      EXPECT_NEAR(gsum[a], 0.0, 1e-13 * gabs) << "particle " << q << " axis " << a;
      EXPECT_NEAR(xs[a], p.x[a][q], 1e-13) << "particle " << q << " axis " << a;  // S reproduces x
      for (int b = 0; b < Dim; ++b)  // grad x = I
        EXPECT_NEAR(xg[a][b], a == b ? 1.0 : 0.0, 1e-12) << "particle " << q << " d x_" << a << " / d x_" << b;
    }
  }
}

// Threads share the stencil's passes: the same entries for one thread and two, and a
// point off the grid (past the cell beyond it) stops the run naming the first such point.
template <int Dim>
void check_threads_and_off_grid(const Case& c) {
  const Grid<Dim> g = mpmx::test::uneven_grid<Dim>();
  Particles<Dim> p = mpmx::test::random_particles<Dim>(g, 600, 5, 2.0);
  SchemeOptions opt;
  opt.scheme = c.scheme;
  opt.alpha = c.alpha;
  opt.subpoints_axes = {2, 3, 2};
  ShapeEvaluator<Dim> eval(opt, g);
  Stencil<Dim> one, two;
  eval(g, p, one);
  eval.set_threads(2);
  eval(g, p, two);
  ASSERT_EQ(one.width, two.width);
  EXPECT_EQ(one.box, two.box);
  EXPECT_EQ(one.node, two.node);
  EXPECT_EQ(one.S, two.S);
  EXPECT_EQ(one.R, two.R);
  for (int a = 0; a < Dim; ++a) EXPECT_EQ(one.G[a], two.G[a]);
  const double past = g.upper[Dim - 1] + 1.5 * (g.upper[Dim - 1] - g.lower[Dim - 1]) / g.cells[Dim - 1];
  p.x[Dim - 1][517] = past;
  p.x[0][431] = std::nan("");
  p.x[Dim - 1][598] = past;
  for (int threads : {1, 2}) {
    eval.set_threads(threads);
    try {
      eval(g, p, two);
      ADD_FAILURE() << "no error on " << threads << " thread(s)";
    } catch (const mpmx::RunError& e) {
      EXPECT_NE(std::string(e.what()).find("particle 431 left the grid"), std::string::npos) << e.what();
    }
  }
  // The axis a point left by is named ("y = ", "z = "), not called x.
  p.x[0][431] = 0.5 * (g.lower[0] + g.upper[0]);
  try {
    eval(g, p, two);
    ADD_FAILURE() << "no error for a point past the last axis";
  } catch (const mpmx::RunError& e) {
    const std::string want = fmt::format("particle 517 left the grid ({} = {}, more than a cell past the grid's upper {} end)",
                                         Dim == 2 ? 'y' : 'z', past, Dim == 2 ? 'y' : 'z');
    EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
  }
}

TEST_P(EverySchemeND, ConsistentIn2D) { check_consistency<2>(GetParam()); }
TEST_P(EverySchemeND, ConsistentIn3D) { check_consistency<3>(GetParam()); }
TEST_P(EverySchemeND, ThreadsAndOffGridIn2D) { check_threads_and_off_grid<2>(GetParam()); }
TEST_P(EverySchemeND, ThreadsAndOffGridIn3D) { check_threads_and_off_grid<3>(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Schemes, EverySchemeND,
                         ::testing::Values(Case{Scheme::mpm, DdmpAlpha::eq_7_3}, Case{Scheme::ugimp, DdmpAlpha::eq_7_3},
                                           Case{Scheme::cpgimp, DdmpAlpha::eq_7_3}, Case{Scheme::cpdi, DdmpAlpha::eq_7_3},
                                           Case{Scheme::ddmp, DdmpAlpha::eq_7_3},
                                           Case{Scheme::ddmp, DdmpAlpha::axis_product},
                                           Case{Scheme::ddmp_subpoints, DdmpAlpha::eq_7_3}),
                         [](const auto& info) {
                           return scheme_name(info.param.scheme) +
                                  (info.param.alpha == DdmpAlpha::axis_product ? "_axis_product" : "");
                         });

// Eq. 7.3 with n_c = 2, d = 1 is eq. 3.27; the generic stencil's DDMP gradient in 1-D is
// eq. 3.31 as the 1-D kernels compute it.
TEST(DdmpND, Eq73IsEq327In1D) {
  for (double f : {0.0, 0.1, 0.25, 0.5, 0.8, 1.0}) {
    const double q = 4.0 * f * (1.0 - f);
    EXPECT_DOUBLE_EQ(shape::ddmp_alpha_nd<1>(&q), shape::ddmp_alpha(f)) << f;
  }
  // At a cell's centre alpha is 0.5 in every dimension, and zero on its faces.
  const double one[3] = {1.0, 1.0, 1.0}, face[3] = {0.0, 1.0, 1.0};
  EXPECT_DOUBLE_EQ(shape::ddmp_alpha_nd<2>(one), 0.5);
  EXPECT_DOUBLE_EQ(shape::ddmp_alpha_nd<3>(one), 0.5);
  EXPECT_EQ(shape::ddmp_alpha_nd<2>(face), 0.0);
  EXPECT_EQ(shape::ddmp_alpha_nd<3>(face), 0.0);
}

TEST(DdmpND, Eq72IsEq331In1D) {
  const Grid<1> g({-1.0}, {3.0}, {20});
  const shape::DdmpTable t(g);
  Particles<1> p;
  p.resize(200);
  for (std::size_t q = 0; q < p.size(); ++q) p.x[0][q] = g.lower[0] + 4.0 * (q + 0.37) / p.size();
  Stencil<1> st;
  ShapeEvaluator<1>({Scheme::ddmp}, g)(g, p, st);
  st = shape::expanded(st, g);
  for (std::size_t q = 0; q < p.size(); ++q) {
    const double xi = (p.x[0][q] - g.lower[0]) * g.inv_dx[0];
    const int c = shape::ddmp_cell(xi, g.cells[0]);
    double ref[4] = {};
    shape::add_ddmp_gradient(g, t, xi, 1.0, c - 1, ref);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(st.G[0][q * 4 + k], ref[k], 1e-14 * (std::abs(ref[k]) + 1.0));
  }
}

// A particle at the centre of a cell row across y (q_y = 1) sees, summed over the y
// nodes, the 1-D gradient along x when alpha is the axis product.
TEST(DdmpND, AxisProductReducesTo1DAcrossY) {
  const Grid<1> g1({0.0}, {2.0}, {8});
  const Grid<2> g2({0.0, 0.0}, {2.0, 0.3}, {8, 1});
  Particles<1> p1;
  Particles<2> p2;
  p1.resize(50);
  p2.resize(50);
  for (std::size_t q = 0; q < 50; ++q) {
    p1.x[0][q] = p2.x[0][q] = 2.0 * (q + 0.5) / 50;
    p2.x[1][q] = 0.15;
  }
  SchemeOptions o;
  o.scheme = Scheme::ddmp;
  o.alpha = DdmpAlpha::axis_product;
  Stencil<1> s1;
  Stencil<2> s2;
  ShapeEvaluator<1>(o, g1)(g1, p1, s1);
  ShapeEvaluator<2>(o, g2)(g2, p2, s2);
  s1 = shape::expanded(s1, g1);
  s2 = shape::expanded(s2, g2);
  for (std::size_t q = 0; q < 50; ++q)
    for (int k = 0; k < 4; ++k) {
      double sum = 0.0;
      for (int j = 0; j < 4; ++j) sum += s2.G[0][q * 16 + j * 4 + k];
      EXPECT_NEAR(sum, s1.G[0][q * 4 + k], 1e-13 * g1.inv_dx[0]) << q << " " << k;
    }
}

}  // namespace
