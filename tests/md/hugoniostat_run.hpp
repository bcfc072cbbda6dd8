#pragma once
// A Hugoniostat run for the tests (md/nose_hoover.hpp, LAMMPS's fix nphug form): a
// 500-atom Mishin copper box at (a, T), relaxed 2 ps in NVE, then held at a stress
// along x for 20 ps, the shocked state averaged over the second half.
#include <cmath>
#include <vector>

#include "mpmx/core/units.hpp"
#include "mpmx/md/hugoniot.hpp"
#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/particles/lattice.hpp"

#include "md_test_util.hpp"

namespace mpmx::test {

inline constexpr int kHugSteps = 20000, kHugEvery = 20;

struct Shocked {
  BlockStats ratio, t;  // V / V0, K over the run's second half
  double p = 0, us = 0, up = 0;     // GPa, km/s
};

inline Shocked hugoniostat(double a, double temperature, double p_gpa) {
  md::System s(md::fcc(5, 5, 5, a), copper());
  s.thermalize(temperature, 3, 0);
  s.advance(2000, 0.001);
  md::NoseHooverOptions o;
  o.temperature = temperature, o.barostat = true, o.isotropic = false, o.axes = {true, false, false};
  o.pressure = {p_gpa, p_gpa, p_gpa}, o.hugoniot = true, o.t_damp = 0.1, o.p_damp = 1.0;
  md::NoseHoover nh(o, s);
  std::vector<double> ratio, t, p;
  for (int step = kHugEvery; step <= kHugSteps; step += kHugEvery) {
    s.advance_coupled(kHugEvery, 0.001, nh);
    if (2 * step <= kHugSteps) continue;
    ratio.push_back(s.box().volume() / nh.v0()), t.push_back(s.temperature()), p.push_back(-s.stress_gpa()[0]);
  }
  Shocked r;
  r.ratio = block_stats(ratio), r.t = block_stats(t);
  r.p = block_stats(p).mean;
  const md::HugoniotPoint jump =
      md::jump_conditions(s, nh.v0(), nh.p0() * units::eV_per_A3_in_GPa, r.ratio.mean * nh.v0(), r.p);
  r.us = jump.us, r.up = jump.up;
  return r;
}

}  // namespace mpmx::test
