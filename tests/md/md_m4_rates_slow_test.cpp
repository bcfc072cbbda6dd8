// ctest-label: slow
// M4 at the slow rate: 1e8 /s to 0.1% strain (10 ps) for 256 and 500 atoms; the slope
// matches C11 = 169.9 GPa within 2% and the 1e9 /s slope within 1% (rate-insensitive).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mpmx/md/lattice.hpp"
#include "mpmx/md/system.hpp"

using namespace mpmx::md;

namespace {

// Least-squares quadratic sigma = c0 + c1 e + c2 e^2; returns c1 (initial slope).
double initial_slope(const std::vector<double>& e, const std::vector<double>& s) {
  double m[3][4] = {};
  for (std::size_t k = 0; k < e.size(); ++k) {
    const double b[3] = {1, e[k], e[k] * e[k]};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += b[i] * b[j];
      m[i][3] += b[i] * s[k];
    }
  }
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 3; ++r)
      if (r != i) {
        const double f = m[r][i] / m[i][i];
        for (int c = 0; c < 4; ++c) m[r][c] -= f * m[i][c];
      }
  return m[1][3] / m[1][1];
}

}  // namespace

// Strain to max_strain at `rate` (1/s) and return the initial slope in GPa.
double uniaxial_slope(int cells, double rate_per_s, double max_strain, Deformation mode,
                      double temperature = 0.0, std::uint64_t seed = 77) {
  PotentialSpec spec;
  spec.file = "/usr/share/lammps/potentials/Cu_mishin1.eam.alloy";
  SystemOptions o;
  o.deformation = mode;
  System s(fcc(cells, cells, cells, 3.615), Potential(spec), o);
  if (temperature > 0) {
    s.thermalize(temperature, seed, static_cast<std::uint64_t>(cells));
    s.advance(2000, 0.001);  // relax at zero strain rate (section 6.2)
  }
  const double rate = rate_per_s * 1e-12;  // 1/ps
  const Mat3 g{rate, 0, 0, 0, 0, 0, 0, 0, 0};
  s.add_streaming_velocity(g);  // the material point already moves with the deformation
  const double dt = 0.001, lx0 = s.box().lx;
  const int total = static_cast<int>(std::ceil(std::log1p(max_strain) / (rate * dt)));
  const int every = std::max(1, total / 200);
  std::vector<double> e{0.0}, sig{s.stress_gpa()[0]};
  for (int done = 0; done < total; done += every) {
    s.advance(every, g, dt);
    e.push_back(s.box().lx / lx0 - 1.0);
    sig.push_back(s.stress_gpa()[0]);
  }
  if (temperature > 0) {  // noisy: a straight line, not a quadratic
    double me = 0, ms = 0, sxy = 0, sxx = 0;
    for (std::size_t k = 0; k < e.size(); ++k) me += e[k] / e.size(), ms += sig[k] / e.size();
    for (std::size_t k = 0; k < e.size(); ++k) sxy += (e[k] - me) * (sig[k] - ms), sxx += (e[k] - me) * (e[k] - me);
    return sxy / sxx;
  }
  return initial_slope(e, sig);
}

TEST(M4Slow, RateAndSizeInsensitive) {
  const double c11 = 169.9;
  const double fast = uniaxial_slope(5, 1e9, 0.001, Deformation::boundary);
  for (int cells : {4, 5}) {
    const double k = uniaxial_slope(cells, 1e8, 0.001, Deformation::boundary);
    std::printf("M4: %d atoms, 1e8/s, 0 K: slope %.2f GPa (1e9/s: %.2f)\n", 4 * cells * cells * cells, k, fast);
    EXPECT_NEAR(k, c11, 0.02 * c11);
    EXPECT_NEAR(k, fast, 0.01 * fast);
  }
}

// 300 K (fig. 5.4 also shows finite temperature): the secant slope over 0.5% strain,
// averaged over 4 seeds, stays within 10% of C11 (thermal softening, C111 curvature and
// noise), and 256 and 500 atoms agree within 10%.
TEST(M4Slow, ThermalSlope) {
  double k256 = 0, k500 = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    k256 += 0.25 * uniaxial_slope(4, 1e9, 0.005, Deformation::boundary, 300.0, seed);
    k500 += 0.25 * uniaxial_slope(5, 1e9, 0.005, Deformation::boundary, 300.0, seed);
  }
  std::printf("M4: 300 K, 1e9/s: slope %.1f GPa (256 atoms), %.1f GPa (500 atoms)\n", k256, k500);
  EXPECT_NEAR(k256, 169.9, 0.1 * 169.9);
  EXPECT_NEAR(k500, 169.9, 0.1 * 169.9);
  EXPECT_NEAR(k256, k500, 0.1 * k500);
}
