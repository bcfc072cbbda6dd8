// ctest-label: slow
// N1 of the validation catalog: the 1-D cases A2 (wave reflection, moving particles) and
// S2 (weak shock, sub-points) written as 2-D and 3-D decks, one cell across y (and z)
// with roller faces, give every particle the 1-D run's x-velocity, stress and position,
// for every scheme.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mpm/mpm_test_util.hpp"

using namespace mpmx;

namespace {

// Max over particles of |a - b|, relative to the largest |a|.
template <int Dim>
void expect_same_as_1d(const app::RunResult& one, const app::RunResultOf<Dim>& nd, double tol,
                       const std::string& what) {
  const auto& p1 = one.state.particles;
  const auto& pn = nd.state.particles;
  ASSERT_EQ(p1.size(), pn.size()) << what;
  auto rel = [&](auto get1, auto getn) {
    double d = 0.0, s = 0.0;
    for (std::size_t q = 0; q < p1.size(); ++q) {
      d = std::max(d, std::abs(get1(q) - getn(q)));
      s = std::max(s, std::abs(get1(q)));
    }
    return s > 0.0 ? d / s : d;
  };
  EXPECT_LE(rel([&](std::size_t q) { return p1.v[0][q]; }, [&](std::size_t q) { return pn.v[0][q]; }), tol)
      << what << ": x-velocity";
  EXPECT_LE(rel([&](std::size_t q) { return p1.stress[0][q]; }, [&](std::size_t q) { return pn.stress[0][q]; }), tol)
      << what << ": stress";
  EXPECT_LE(rel([&](std::size_t q) { return p1.x[0][q]; }, [&](std::size_t q) { return pn.x[0][q]; }), tol)
      << what << ": position";
  // Nothing moved across y.
  double vy = 0.0;
  for (std::size_t q = 0; q < pn.size(); ++q) vy = std::max(vy, std::abs(pn.v[1][q]));
  EXPECT_EQ(vy, 0.0) << what;
}

template <class T>
void set_scheme(toml::table& t, const std::string& name, T subpoints) {
  auto& s = *t["scheme"].as_table();
  s.insert_or_assign("name", name);
  s.erase("subpoints");
  s.erase("alpha");
  if (name == "ddmp_subpoints") s.insert_or_assign("subpoints", subpoints);
  if (name.rfind("ddmp", 0) == 0 && !std::is_same_v<T, int>) s.insert_or_assign("alpha", "axis_product");
}

}  // namespace

TEST(N1, WaveReflectionIn2DAnd3DEqualsTheOneDimensionalRun) {
  for (const std::string scheme : {"mpm", "ugimp", "cpgimp", "cpdi", "ddmp", "ddmp_subpoints"}) {
    auto shorten = [&](toml::table& t, auto sub) {
      t["time"].as_table()->insert_or_assign("end", 0.15);
      t["output"].as_table()->insert_or_assign("times", toml::array{0.15});
      set_scheme(t, scheme, sub);
    };
    const auto one = test::run(test::deck_with(test::example("A2_wave_reflection_moving.toml"), [&](toml::table& t) {
      shorten(t, 4);
      t.erase("reference");
    }));
    toml::array sub2{4, 1}, sub3{4, 1, 1};
    const auto two = test::run_dim<2>(test::deck_with(test::example("N1_wave_reflection_2d.toml"),
                                                [&](toml::table& t) { shorten(t, sub2); }));
    expect_same_as_1d<2>(one, two, 1e-10, scheme + " 2-D");
    if (scheme == "ddmp" || scheme == "mpm" || scheme == "cpdi") {
      const auto three = test::run_dim<3>(test::deck_with(test::example("N1_wave_reflection_3d.toml"),
                                                    [&](toml::table& t) { shorten(t, sub3); }));
      expect_same_as_1d<3>(one, three, 1e-10, scheme + " 3-D");
    }
  }
}

TEST(N1, ShockTubeWithSubpointsIn2DEqualsTheOneDimensionalRun) {
  auto shorten = [](toml::table& t) {
    t["time"].as_table()->insert_or_assign("end", 25.0);
    t["output"].as_table()->insert_or_assign("times", toml::array{25.0});
  };
  const auto one = test::run(test::deck_with(test::example("S2_ddmp_2ppc_16sub.toml"), [&](toml::table& t) {
    shorten(t);
    t.erase("reference");
  }));
  const auto two = test::run_dim<2>(test::deck_with(test::example("N1_shock_tube_subpoints_2d.toml"), shorten));
  expect_same_as_1d<2>(one, two, 1e-10, "ddmp_subpoints 2 ppc x 16");
}
