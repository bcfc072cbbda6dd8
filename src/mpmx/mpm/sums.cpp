#include "mpmx/mpm/sums.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpmx/mpm/points.hpp"

namespace mpmx::mpm {

template <int Dim>
Sums sums(const State<Dim>& s) {
  const auto& p = s.particles;
  const auto view = points(p);
  const bool elastic_1d = Dim == 1 && s.material->stored_energy_in_1d();
  auto add_1d = [&](Sums& r, std::size_t q) {
    const double mv = p.mass[q] * p.v[0][q];
    r.momentum[0] += mv;
    r.kinetic += 0.5 * mv * p.v[0][q];
    r.abs_momentum += std::abs(mv);
    if (elastic_1d) r.internal += 0.5 * p.volume0[q] * p.stress[0][q] * p.strain[0][q];
    r.mass += p.mass[q];
  };
  Sums r;
  const std::size_t n = p.size();
  if constexpr (Dim == 1) {
    for (std::size_t q = 0; q < n; ++q) add_1d(r, q);
  } else {
    // Blocks of a fixed size on the threads, added in block order; within a block, eight
    // lanes by the point's place in it, added in lane order (the loop vectorises): the
    // same sums for any thread count.
    constexpr std::size_t kBlock = 2048, kLanes = 8;
    std::vector<Sums> part((n + kBlock - 1) / kBlock);
#pragma omp parallel for schedule(static) num_threads(s.threads) if (s.threads > 1)
    for (std::size_t b = 0; b < part.size(); ++b) {
      const std::size_t q0 = b * kBlock, q1 = std::min(n, q0 + kBlock);
      double ke[kLanes] = {}, am[kLanes] = {}, m[kLanes] = {}, mom[Dim][kLanes] = {};
      auto lane = [&](std::size_t q, std::size_t l) {
        double v2 = 0.0;
        for (int a = 0; a < Dim; ++a) {
          mom[a][l] += p.mass[q] * p.v[a][q];
          v2 += p.v[a][q] * p.v[a][q];
        }
        ke[l] += 0.5 * p.mass[q] * v2;
        am[l] += p.mass[q] * std::sqrt(v2);
        m[l] += p.mass[q];
      };
      std::size_t q = q0;
      for (; q + kLanes <= q1; q += kLanes)
        for (std::size_t l = 0; l < kLanes; ++l) lane(q + l, l);
      for (std::size_t l = 0; q < q1; ++q, ++l) lane(q, l);
      Sums& out = part[b];
      for (std::size_t l = 0; l < kLanes; ++l) {
        out.kinetic += ke[l], out.abs_momentum += am[l], out.mass += m[l];
        for (int a = 0; a < Dim; ++a) out.momentum[a] += mom[a][l];
      }
      out.internal = s.material->stored_energy_sum(view, q0, q1);
    }
    for (const Sums& b : part) {
      r.kinetic += b.kinetic, r.abs_momentum += b.abs_momentum, r.internal += b.internal, r.mass += b.mass;
      for (int a = 0; a < Dim; ++a) r.momentum[a] += b.momentum[a];
    }
  }
  return r;
}

template Sums sums<1>(const State<1>&);
template Sums sums<2>(const State<2>&);
template Sums sums<3>(const State<3>&);

}  // namespace mpmx::mpm
