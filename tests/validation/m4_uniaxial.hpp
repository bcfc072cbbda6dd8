#pragma once
// M4 helpers shared by the uniaxial-strain tests: strain an fcc Cu box along x at a
// given rate and fit the initial slope of sigma_xx(e).
#include <cmath>
#include <cstdint>
#include <vector>

#include "mpmx/md/system.hpp"
#include "mpmx/particles/lattice.hpp"
#include "../md/md_test_util.hpp"

namespace mpmx::test {

using namespace mpmx::md;


// Least-squares quadratic sigma = c0 + c1 e + c2 e^2; returns c1 (initial slope).
inline double initial_slope(const std::vector<double>& e, const std::vector<double>& s) {
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


// Strain to max_strain at `rate` (1/s) and return the initial slope in GPa.
inline double uniaxial_slope(int cells, double rate_per_s, double max_strain, Deformation mode,
                      double temperature = 0.0, std::uint64_t seed = 77) {
  SystemOptions o;
  o.deformation = mode;
  System s(fcc(cells, cells, cells, 3.615), copper(), o);
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

}  // namespace mpmx::test
