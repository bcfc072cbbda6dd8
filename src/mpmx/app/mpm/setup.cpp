#include "mpmx/app/mpm/setup.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "mpmx/app/mpm/bodies.hpp"
#include "mpmx/app/mpm/materials.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/material/composite.hpp"
#include "mpmx/mpm/points.hpp"

namespace mpmx::app {

using namespace mpm;

namespace {

// The manufactured solution of [manufactured] for the deck's linear elastic law (its
// Lame constants; the reference entry requires that law).
reference::AxisAligned manufactured_solution(const MpmConfig& c, int dim) {
  reference::AxisAligned m;
  m.A = c.manufactured.amplitude;
  m.c = c.manufactured.speed;
  m.rho0 = c.material.density;
  m.dim = dim;
  if (const auto e = c.material.spec ? c.material.spec->isotropic_elastic() : std::nullopt) {
    m.mu = e->E / (2.0 * (1.0 + e->nu));
    m.lambda = e->E * e->nu / ((1.0 + e->nu) * (1.0 - 2.0 * e->nu));
  }
  return m;
}

}  // namespace

PlacedPoints placed_points(const MpmConfig& c) {
  PlacedPoints r;
  auto& at = r.at;
  auto& owner = r.owner;
  place_points(c, [&](const std::array<double, 3>& x, int body) {
    at.push_back(x);
    owner.push_back(body);
  });
  if (at.empty()) throw InputError("no material points: no [[body]] region holds a point centre of the grid");

  // The laws in play: the deck's [material] first, then each body's own. Points are
  // ordered by law (stable, so a one-law deck keeps the grid order) and each law gets
  // its block (material/composite.hpp).
  auto& laws = r.laws;
  laws = {c.material.spec.get()};
  std::vector<int> law(at.size(), 0);
  for (std::size_t q = 0; q < at.size(); ++q) {
    const int b = owner[q];
    if (b < 0 || !c.bodies[b].material) continue;
    const material::Model* m = c.bodies[b].material.get();
    auto it = std::find(laws.begin(), laws.end(), m);
    if (it == laws.end()) it = laws.insert(laws.end(), m);
    law[q] = static_cast<int>(it - laws.begin());
  }
  std::vector<std::size_t> order(at.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return law[a] < law[b]; });
  std::vector<std::array<double, 3>> at2(at.size());
  std::vector<int> owner2(at.size()), law2(at.size());
  for (std::size_t k = 0; k < order.size(); ++k) at2[k] = at[order[k]], owner2[k] = owner[order[k]], law2[k] = law[order[k]];
  at.swap(at2), owner.swap(owner2);
  r.law.swap(law2);
  return r;
}

template <int Dim>
State<Dim> make_state(const MpmConfig& c, bool initialize_material, int threads) {
  State<Dim> s;
  std::array<double, Dim> lo, hi;
  std::array<int, Dim> n;
  for (int d = 0; d < Dim; ++d) lo[d] = c.lower_all[d], hi[d] = c.upper_all[d], n[d] = c.cells_all[d];
  s.grid = Grid<Dim>(lo, hi, n);
  s.move = c.move;
  s.small_strain = c.material.small_strain;
  s.midpoint_gradient = c.scheme.midpoint_gradient;
  s.musl = c.scheme.musl;
  s.viscosity = c.viscosity;
  s.boundary = c.boundary;

  std::array<double, Dim> l;
  for (int d = 0; d < Dim; ++d) l[d] = s.grid.dx[d] / c.per_cell_all[d];
  PlacedPoints placed = placed_points(c);
  auto& at = placed.at;
  const auto& owner = placed.owner;
  const auto& law = placed.law;
  const auto& laws = placed.laws;
  if (law.front() == law.back()) {
    s.material = material::make<Dim>(*laws[law.front()]);
  } else {
    std::vector<typename material::Composite<Dim>::Part> parts;
    for (std::size_t q = 0; q < law.size(); ++q) {
      if (q == 0 || law[q] != law[q - 1]) parts.push_back({material::make<Dim>(*laws[law[q]]), q, 0});
      ++parts.back().count;
    }
    if constexpr (Dim > 1) s.material = std::make_unique<material::Composite<Dim>>(std::move(parts));
  }
  s.material->use_run_threads(threads);

  auto& p = s.particles;
  p.resize(at.size());
  const double dx = c.dx(), L = c.upper - c.lower;
  const bool solid = c.material.solid();  // every law of a deck is of one kind (io/mpm_deck.cpp)
  double V = 1.0;
  for (int d = 0; d < Dim; ++d) V *= l[d];
  for (std::size_t q = 0; q < at.size(); ++q) {
    for (int d = 0; d < Dim; ++d) {
      p.x[d][q] = at[q][d];
      p.length[d * Dim + d][q] = l[d];
      if (owner[q] >= 0) p.v[d][q] = c.bodies[owner[q]].velocity[d];
    }
    if (owner[q] >= 0 && Dim == 2) {  // omega x (x - centre)
      const Body& b = c.bodies[owner[q]];
      p.v[0][q] -= b.angular_velocity * (at[q][1] - b.center[1]);
      p.v[1 % Dim][q] += b.angular_velocity * (at[q][0] - b.center[0]);
    }
    p.volume[q] = p.volume0[q] = V;
    p.body[q] = std::max(owner[q], 0);
    p.law[q] = law[q];
    const double v_profile = c.velocity(c.velocity.along(at[q], Dim), c.lower, L, dx);
    for (int d = 0; d < Dim; ++d) p.v[d][q] += v_profile * c.velocity.normal[d];
    const material::Model& m = *laws[law[q]];
    double rho = m.density();
    if (solid) {
      p.strain[0][q] = c.strain(c.strain.along(at[q], Dim), c.lower, L, dx);
      if (m.density_of_unstrained()) rho /= 1.0 + p.strain[0][q];
    } else {
      const double pr = c.pressure(c.pressure.along(at[q], Dim), c.lower, L, dx);
      if (std::isfinite(m.density_at_pressure(1.0))) rho = m.density_at_pressure(pr);  // isothermal gas: p sets rho
      for (int d = 0; d < Dim; ++d) p.stress[d * Dim + d][q] = -pr;  // read by the adiabatic gas
      if constexpr (Dim == 2) p.stress_zz[q] = -pr;
    }
    p.mass[q] = rho * V;
  }
  if (c.tensor_viscosity)
    for (auto& a : p.viscous) a.assign(p.size(), 0.0);
  s.tensor_viscosity = {c.tensor_viscosity, c.c_L, c.c_q};
  double mean_mass = 0.0;
  for (double m : p.mass) mean_mass += m;
  mean_mass /= static_cast<double>(p.size());
  s.mass_distribution.on = c.mass_distribution;
  s.mass_distribution.threshold = c.mass_fraction * mean_mass;
  if constexpr (Dim > 1)
    if (c.manufactured.on) {
      auto m = std::make_shared<Manufactured<Dim>>(manufactured_solution(c, Dim), p);
      m->start(p);
      s.manufactured = std::move(m);
    }
  if (initialize_material) s.material->initialize(points(p));
  s.shape = std::make_unique<ShapeEvaluator<Dim>>(c.scheme, s.grid);
  // Threads over particles pay only on large batches (a parallel region costs microseconds,
  // much more on a busy machine); results are the same either way.
  constexpr std::size_t kParallelFrom = 8192;
  // Without --threads the continuum stays on one: on a shared machine a second thread
  // waits for a busy core (two free cores give 1.8-2x, docs/performance.md).
  s.threads = p.size() < kParallelFrom || threads <= 0 ? 1 : threads;
  s.shape->set_threads(s.threads);
  if constexpr (Dim > 1) s.material->set_threads(s.threads);
  return s;
}

template State<1> make_state<1>(const MpmConfig&, bool, int);
template State<2> make_state<2>(const MpmConfig&, bool, int);
template State<3> make_state<3>(const MpmConfig&, bool, int);

}  // namespace mpmx::app
