// ctest-label: unit
// The fused 1-D kernels (fused1d/linear_fused) are the stencil step regrouped: for every
// scheme they cover and every branch they take (finite and small strain, gas and solid,
// viscosity, particles crossing cells, sub-points beyond the neighbouring cell) they
// must give the stencil step's particles and nodes to round-off, on every vector path
// this machine has (each test runs once per path, named by its suffix).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mpm_test_util.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/isa.hpp"
#include "mpmx/mpm/fused1d/linear_fused.hpp"
#include "mpmx/app/mpm/setup.hpp"
#include "mpmx/mpm/step.hpp"

using namespace mpmx;

namespace {

double max_abs(const std::vector<double>& a) {
  double m = 0.0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

// Largest difference of a and b relative to the field's largest magnitude.
double rel_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  const double scale = std::max(max_abs(a), max_abs(b));
  return scale > 0.0 ? d / scale : d;
}

// Steps both paths from the same state, compares each step to round-off, then hands the
// fused particles to the stencil path, so that each comparison is of one step and
// differences do not grow through the cell crossings.
struct Covered {
  std::size_t strays = 0;  // particles at most with sub-points beyond the neighbouring cells
  int steps_past = 0;      // steps with a particle past an end of the grid
};
Covered expect_same_steps(const app::MpmConfig& c, int steps, const std::string& what) {
  mpm::State<1> fused = app::make_state(c), plain = app::make_state(c);
  const std::vector<double> x0 = fused.particles.x[0];
  const double tol = 1e-12;
  double worst[6] = {};
  double work_scale = 0.0;
  Covered cov;
  for (int k = 0; k < steps; ++k) {
    mpm::step(fused, c.dt);
    mpm::step_stencil(plain, c.dt);
    cov.strays = std::max(cov.strays, fused.linear_cells.stray.size());
    cov.steps_past += !fused.linear_cells.inside;
    const auto& a = fused.particles;
    const auto& b = plain.particles;
    const double d[6] = {rel_diff(a.x[0], b.x[0]),           rel_diff(a.v[0], b.v[0]),
                         rel_diff(a.grad_v[0], b.grad_v[0]), rel_diff(a.stress[0], b.stress[0]),
                         rel_diff(a.volume, b.volume),
                         rel_diff(fused.grid.velocity_L[0], plain.grid.velocity_L[0])};
    for (int f = 0; f < 6; ++f) worst[f] = std::max(worst[f], d[f]);
    // The work tally swings through zero: its tolerance is relative to its largest size.
    work_scale = std::max(work_scale, std::abs(plain.tallies.stress_work));
    EXPECT_NEAR(fused.tallies.stress_work, plain.tallies.stress_work, 1e-12 * work_scale + 1e-300)
        << what << " step " << k;
    EXPECT_EQ(fused.step, plain.step);
    plain.particles = fused.particles;
    plain.tallies = fused.tallies;
  }
  const char* field[6] = {"x", "v", "grad v", "stress", "volume", "nodal v^L"};
  for (int f = 0; f < 6; ++f) EXPECT_LT(worst[f], tol) << what << ": " << field[f];
  double crossed = 0.0;
  for (std::size_t q = 0; q < x0.size(); ++q)
    crossed = std::max(crossed, std::abs(fused.particles.x[0][q] - x0[q]) * fused.grid.inv_dx[0]);
  EXPECT_GT(crossed, 0.5) << what;  // particles crossed cells
  std::printf("%-22s particles moved up to %.2f cells, largest difference %.1e, %zu strays, %d steps past the grid\n",
              what.c_str(), crossed, *std::max_element(worst, worst + 6), cov.strays, cov.steps_past);
  return cov;
}

template <class Edit>
app::MpmConfig with_scheme(const std::string& deck, const std::string& scheme, int sub, Edit edit) {
  return test::deck_with(test::example(deck), [&](toml::table& t) {
    auto& s = *t["scheme"].as_table();
    s.insert_or_assign("name", scheme);
    s.erase("subpoints");
    if (sub > 0) s.insert_or_assign("subpoints", sub);
    t.erase("reference");
    t.erase("output");
    edit(t);
  });
}

const std::pair<const char*, int> kFused[] = {{"mpm", 0}, {"ddmp", 0}, {"ddmp_subpoints", 4}};

class FusedPath : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    mpmx::isa_use(GetParam());
    ASSERT_EQ(mpm::shape::isa_dispatched(), GetParam());
  }
  void TearDown() override { mpmx::isa_use(mpmx::isa_supported().front()); }
};

INSTANTIATE_TEST_SUITE_P(Isa, FusedPath, ::testing::ValuesIn(mpmx::isa_supported()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// A driven elastic bar, small strain (the ADMPM bench's fast path) and finite strain; 2
// and 4 particles per cell (runs of four take the vector per-cell sums). At 4 the end is
// driven outwards first (as in the ADMPM bench), so that its particles pass the grid's
// end for a while (a zero gradient there: the kernels' other branch).
TEST_P(FusedPath, ElasticBarMatchesStencil) {
  for (const auto& [scheme, sub] : kFused)
    for (const bool small : {true, false})
      for (const int ppc : {2, 4}) {
        const auto c = with_scheme("A2_wave_reflection_moving.toml", scheme, sub, [&](toml::table& t) {
          t["material"].as_table()->insert_or_assign("small_strain", small);
          t["particles"].as_table()->insert_or_assign("per_cell", ppc);
          t["boundary"].as_table()->insert_or_assign(
              "right", toml::table{{"type", "velocity"}, {"amplitude", ppc == 4 ? 0.04 : -0.2}, {"omega", 10.0}});
          t["time"].as_table()->insert_or_assign("dt", 1e-3);
        });
        const Covered cov = expect_same_steps(
            c, 1000, std::string(scheme) + (small ? " small " : " finite ") + std::to_string(ppc) + " ppc");
        if (ppc == 4) {
          EXPECT_GT(cov.steps_past, 0) << scheme;
        }
      }
}

// The isothermal shock tube with viscosity: a gas, particles crossing cells, and with one
// particle per cell and 16 sub-points, sub-points more than a cell from their particle.
TEST_P(FusedPath, ShockTubeMatchesStencil) {
  for (const auto& [scheme, subpoints] : kFused) {
    const int sub = subpoints;  // a lambda captures a copy (clang 14 takes no structured binding)
    const auto c = with_scheme("S3_ddmp_1ppc_16sub.toml", scheme, sub ? 16 : 0, [&](toml::table& t) {
      // The original MPM with one particle per cell flies apart on this shock (S1).
      if (sub == 0) t["particles"].as_table()->insert_or_assign("per_cell", 4);
      t.insert_or_assign("viscosity", toml::table{{"linear", 0.1}});
    });
    const Covered cov = expect_same_steps(c, 300, scheme);
    if (sub > 0) {
      EXPECT_GT(cov.strays, 0u);  // the stray sub-point path was taken
    }
  }
}

// The gas wave of A4 (adiabatic gas, small strain).
TEST_P(FusedPath, GasWaveMatchesStencil) {
  for (const auto& [scheme, sub] : kFused) {
    const auto c = with_scheme("A4_gas_wave.toml", scheme, sub, [](toml::table& t) {
      t["boundary"].as_table()->insert_or_assign(
          "right", toml::table{{"type", "velocity"}, {"amplitude", -0.1}, {"omega", 10.0}});
      t["time"].as_table()->insert_or_assign("dt", 1e-3);
    });
    expect_same_steps(c, 1000, scheme);
  }
}

// The fused p2g takes the cell order it found at the last step as given and tests it as
// the per-cell sums go (the locate pass leaves it out); particles found out of order
// then take the unordered sums. Two particles of different cells swap places in the
// arrays after a step in order: the next step must still be the stencil step's.
TEST_P(FusedPath, OrderLostBetweenStepsMatchesStencil) {
  for (const auto& [scheme, sub] : kFused) {
    // A1's standing wave: every particle moves from the start.
    const auto c = with_scheme("A1_standing_wave_moving.toml", scheme, sub, [](toml::table& t) {
      t["particles"].as_table()->insert_or_assign("per_cell", 4);
    });
    mpm::State<1> fused = app::make_state(c), plain = app::make_state(c);
    mpm::step(fused, c.dt);
    ASSERT_TRUE(fused.linear_cells.ordered) << scheme;
    auto swap_particles = [](mpm::Particles<1>& p, std::size_t i, std::size_t j) {
      for (auto* a : {&p.x[0], &p.v[0], &p.mass, &p.volume, &p.volume0, &p.length[0], &p.strain[0],
                      &p.stress[0], &p.grad_v[0], &p.viscous_pressure})
        std::swap((*a)[i], (*a)[j]);
    };
    swap_particles(fused.particles, 5, 40);  // cells 1 and 10
    plain.particles = fused.particles;
    plain.tallies = fused.tallies;
    plain.time = fused.time;
    plain.step = fused.step;
    mpm::step(fused, c.dt);
    mpm::step_stencil(plain, c.dt);
    EXPECT_FALSE(fused.linear_cells.ordered) << scheme;
    const auto& a = fused.particles;
    const auto& b = plain.particles;
    EXPECT_LT(rel_diff(a.x[0], b.x[0]), 1e-12) << scheme;
    EXPECT_LT(rel_diff(a.v[0], b.v[0]), 1e-12) << scheme;
    EXPECT_LT(rel_diff(a.stress[0], b.stress[0]), 1e-12) << scheme;
    EXPECT_LT(rel_diff(fused.grid.velocity_L[0], plain.grid.velocity_L[0]), 1e-12) << scheme;
    EXPECT_LT(rel_diff(fused.grid.force[0], plain.grid.force[0]), 1e-12) << scheme;
  }
}

// The paths by name (as MPMX_ISA names them): each this machine has can be taken, and an
// unknown one is an input error that leaves the path as it was.
TEST(FusedIsa, PathsByName) {
  const std::vector<std::string> paths = mpmx::isa_supported();
  ASSERT_FALSE(paths.empty());
  for (const std::string& name : paths) {
    mpmx::isa_use(name);
    EXPECT_EQ(mpmx::isa_chosen(), name);
    EXPECT_EQ(mpm::shape::isa_dispatched(), name);
  }
  EXPECT_THROW(mpmx::isa_use("avx1024"), InputError);
  EXPECT_EQ(mpmx::isa_chosen(), paths.back());
  EXPECT_EQ(mpm::shape::isa_dispatched(), paths.back());
  mpmx::isa_use(paths.front());
}

}  // namespace
