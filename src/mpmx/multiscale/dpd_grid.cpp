#include "mpmx/multiscale/dpd_grid.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/material/points.hpp"

namespace mpmx::multiscale {

namespace {

constexpr std::uint8_t kRigid = 0, kDpd = 1, kPoint = 2;

// The 8 corners of a cell: offsets along x, y, z.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};

}  // namespace

DpdGrid::DpdGrid(double cell, const particles::Vec3& lo, const particles::Vec3& hi, int threads) : threads_(threads) {
  if (!(cell > 0) || !std::isfinite(cell)) throw InputError(fmt::format("grid.cell = {}: must be positive", cell));
  std::array<double, 3> a{}, b{};
  std::array<int, 3> n{};
  for (int d = 0; d < 3; ++d) {
    if (!(hi[d] > lo[d])) throw InputError(fmt::format("dpd grid: empty extent along axis {}", d));
    const double cells = std::ceil((hi[d] - lo[d]) / cell);
    if (cells > 4096) throw InputError(fmt::format("grid.cell = {} A: {} cells along axis {} (at most 4096)", cell, cells, d));
    n[d] = static_cast<int>(cells);
    a[d] = lo[d];
    b[d] = lo[d] + n[d] * cell;
  }
  make_grid(a, b, n);
}

void DpdGrid::make_grid(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<int, 3>& n) {
  g_ = mpm::Grid<3>(a, b, n);
  for (int k = 0; k < 8; ++k)
    off_[k] = static_cast<std::size_t>(kCorner[k][0] * g_.stride[0] + kCorner[k][1] * g_.stride[1] +
                                       kCorner[k][2] * g_.stride[2]);
  for (auto& v : node_acc_) v.assign(g_.storage, 0.0);
  touched_.assign(g_.storage, 0);
}

void DpdGrid::set_continuum(int group, std::unique_ptr<material::Material<3>> law, const dpd::Particles& p,
                            double volume_per_point) {
  cont_group_ = group;
  law_ = std::move(law);
  cont_id_.clear();
  std::int64_t max_id = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    max_id = std::max(max_id, p.id[i]);
    if (p.group[i] == group) cont_id_.push_back(p.id[i]);
  }
  std::sort(cont_id_.begin(), cont_id_.end());
  slot_of_id_.assign(static_cast<std::size_t>(max_id) + 1, -1);
  for (std::size_t k = 0; k < cont_id_.size(); ++k) slot_of_id_[cont_id_[k]] = static_cast<std::int32_t>(k);
  const std::size_t m = cont_id_.size();
  mass_.assign(m, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.group[i] == group) mass_[slot_of_id_[p.id[i]]] = p.mass[i];
  volume_.assign(m, volume_per_point);
  volume0_.assign(m, volume_per_point);
  length_.assign(m, g_.dx[0]);
  for (int c = 0; c < 9; ++c) grad_v_[c].assign(m, 0.0), stress_[c].assign(m, 0.0), strain_[c].assign(m, 0.0);
  law_->initialize(points());
}

// Trilinear shape function of corner k and its gradient, for a particle at f in its cell.
double DpdGrid::corner(const Stencil& s, int k, double G[3]) const {
  double w[3], dw[3];
  for (int d = 0; d < 3; ++d) {
    const bool up = kCorner[k][d] == 1;
    w[d] = up ? s.f[d] : 1.0 - s.f[d];
    dw[d] = (up ? 1.0 : -1.0) * g_.inv_dx[d];
  }
  G[0] = dw[0] * w[1] * w[2], G[1] = w[0] * dw[1] * w[2], G[2] = w[0] * w[1] * dw[2];
  return w[0] * w[1] * w[2];
}

void DpdGrid::report(toml::table& out) const {
  out.insert("grid_cell_A", g_.dx[0]);
  out.insert("grid_cells", toml::array{g_.cells[0], g_.cells[1], g_.cells[2]});
  out.insert("grid_lower_A", toml::array{g_.lower[0], g_.lower[1], g_.lower[2]});
  out.insert("small_mass_node_steps_left_out", skipped_);
  if (!cont_id_.empty()) {
    out.insert("continuum_points", static_cast<std::int64_t>(cont_id_.size()));
    out.insert("continuum_law", law_->name());
    out.insert("interface", reaction_ ? "pair_reaction" : "seed");
    out.insert("continuum_c11_c12_c44_GPa", toml::array{constants_[0], constants_[1], constants_[2]});
  }
}

double DpdGrid::continuum_stress(std::int64_t id, int component) const {
  if (id < 0 || static_cast<std::size_t>(id) >= slot_of_id_.size() || slot_of_id_[id] < 0) return 0.0;
  return stress_[component][slot_of_id_[id]];
}

material::Points<3> DpdGrid::points() {
  material::Points<3> v;
  v.n = cont_id_.size();
  for (int c = 0; c < 9; ++c) v.grad_v[c] = grad_v_[c].data(), v.stress[c] = stress_[c].data(), v.strain[c] = strain_[c].data();
  v.mass = mass_.data(), v.volume = volume_.data(), v.volume0 = volume0_.data();
  for (int d = 0; d < 3; ++d) v.length[d] = length_.data();
  return v;
}

void DpdGrid::locate(const dpd::Particles& p) {
  const std::size_t n = p.size();
  st_.resize(n);
  moves_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const int grp = p.group[i];
    moves_[i] = grp == dpd::kMobile ? kDpd : grp == cont_group_ ? kPoint : kRigid;
    if (moves_[i] == kRigid) continue;
    const double x[3] = {p.x[i], p.y[i], p.z[i]};
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) {
      const double s = (x[d] - g_.lower[d]) * g_.inv_dx[d];
      if (!(s >= 0.0 && s < g_.cells[d]))
        throw RunError(fmt::format("DPD/MPM grid: particle {} at ({:.4g}, {:.4g}, {:.4g}) A has left the grid "
                                   "[{:.4g}, {:.4g}] along axis {}: enlarge grid.margin",
                                   p.id[i], x[0], x[1], x[2], g_.lower[d], g_.upper[d], d));
      c[d] = static_cast<int>(s);
      st_[i].f[d] = s - c[d];
    }
    st_[i].base = g_.index(c);
  }
}

void DpdGrid::move(dpd::Particles& p, double dt) {
  const std::size_t n = p.size();
  locate(p);

  // Only the nodes the particles touch are cleared and solved (a fine grid over a wide
  // margin is mostly empty): last step's are cleared, this step's listed in p2g order.
  for (std::size_t node : active_) {
    g_.mass[node] = 0.0;
    touched_[node] = 0;
    for (int d = 0; d < 3; ++d) g_.momentum[d][node] = 0.0, g_.force[d][node] = 0.0;
  }
  active_.clear();
  // s1, s2, s3a, s3b: serial, so every node sums its particles in index order.
  double mmax = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (moves_[i] == kRigid) continue;
    const Stencil& s = st_[i];
    const double m = p.mass[i];
    mmax = std::max(mmax, m);
    const double mv[3] = {m * p.vx[i], m * p.vy[i], m * p.vz[i]};
    double f[3] = {units::ftm2v * p.fx[i], units::ftm2v * p.fy[i], units::ftm2v * p.fz[i]};  // amu A/ps^2
    double sig[9] = {};
    const bool point = moves_[i] == kPoint;
    if (point) {
      const std::size_t k = static_cast<std::size_t>(slot_of_id_[p.id[i]]);
      for (int c = 0; c < 9; ++c) sig[c] = units::ftm2v * volume_[k] * stress_[c][k];
    }
    for (int k = 0; k < 8; ++k) {
      double G[3];
      const double S = corner(s, k, G);
      const std::size_t node = s.base + off_[k];
      if (!touched_[node]) touched_[node] = 1, active_.push_back(node);
      g_.mass[node] += m * S;
      for (int a = 0; a < 3; ++a) {
        g_.momentum[a][node] += mv[a] * S;
        if (point) {
          g_.force[a][node] -= sig[3 * a] * G[0] + sig[3 * a + 1] * G[1] + sig[3 * a + 2] * G[2];
          if (reaction_) g_.force[a][node] += f[a] * S;  // the DPD neighbours' pull and push
        } else {
          g_.force[a][node] += f[a] * S;
        }
      }
    }
  }
  // s5 and the nodal acceleration; nodes of near-zero mass are left out (here and in s11).
  m_eps_ = 1e-12 * mmax;
  const double m_eps = m_eps_;
  std::int64_t skipped = 0;
  const std::size_t nactive = active_.size();
#pragma omp parallel for schedule(static) reduction(+ : skipped) num_threads(threads_) if (threads_ > 1)
  for (std::size_t k = 0; k < nactive; ++k) {
    const std::size_t node = active_[k];
    const double m = g_.mass[node];
    const bool use = m > m_eps;
    if (!use && m > 0) ++skipped;
    for (int a = 0; a < 3; ++a) {
      g_.momentum[a][node] += dt * g_.force[a][node];
      g_.velocity_L[a][node] = use ? g_.momentum[a][node] / m : 0.0;
      node_acc_[a][node] = use ? g_.force[a][node] / m : 0.0;
    }
  }
  skipped_ += skipped;
  // s6-s8 for the particles on the grid; rigid ones at their velocity.
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1)
  for (std::size_t i = 0; i < n; ++i) {
    if (moves_[i] != kRigid) {
      const Stencil& s = st_[i];
      double acc[3] = {}, vbar[3] = {};
      for (int k = 0; k < 8; ++k) {
        double G[3];
        const double S = corner(s, k, G);
        const std::size_t node = s.base + off_[k];
        for (int a = 0; a < 3; ++a) acc[a] += node_acc_[a][node] * S, vbar[a] += g_.velocity_L[a][node] * S;
      }
      p.vx[i] += dt * acc[0], p.vy[i] += dt * acc[1], p.vz[i] += dt * acc[2];
      p.x[i] += dt * vbar[0], p.y[i] += dt * vbar[1], p.z[i] += dt * vbar[2];
    } else {
      p.x[i] += dt * p.vx[i], p.y[i] += dt * p.vy[i], p.z[i] += dt * p.vz[i];
    }
  }
  if (law_ && !cont_id_.empty()) update_continuum(p, dt);
}

// s10-s14 with the stencil of x^t (the seed's N_i(x_p^t), G_i(x_p^t)).
void DpdGrid::update_continuum(dpd::Particles& p, double dt) {
  const std::size_t n = p.size();
  // s10, s11: the new momenta of every particle on the grid, over the node masses of s1.
  for (std::size_t node : active_)
    for (int a = 0; a < 3; ++a) g_.momentum[a][node] = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (moves_[i] == kRigid) continue;
    const double m = p.mass[i], mv[3] = {m * p.vx[i], m * p.vy[i], m * p.vz[i]};
    for (int k = 0; k < 8; ++k) {
      double G[3];
      const double S = corner(st_[i], k, G);
      for (int a = 0; a < 3; ++a) g_.momentum[a][st_[i].base + off_[k]] += mv[a] * S;
    }
  }
  for (std::size_t node : active_)
    for (int a = 0; a < 3; ++a)
      g_.velocity[a][node] = g_.mass[node] > m_eps_ ? g_.momentum[a][node] / g_.mass[node] : 0.0;
  // s12: L_p = sum_i v_i G_i(x_p^t); the volume follows det(I + dt L) to first order.
#pragma omp parallel for schedule(static) num_threads(threads_) if (threads_ > 1)
  for (std::size_t i = 0; i < n; ++i) {
    if (moves_[i] != kPoint) continue;
    const std::size_t q = static_cast<std::size_t>(slot_of_id_[p.id[i]]);
    double L[9] = {};
    for (int k = 0; k < 8; ++k) {
      double G[3];
      corner(st_[i], k, G);
      const std::size_t node = st_[i].base + off_[k];
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) L[3 * a + b] += g_.velocity[a][node] * G[b];
    }
    for (int c = 0; c < 9; ++c) grad_v_[c][q] = L[c];
    volume_[q] *= 1.0 + dt * (L[0] + L[4] + L[8]);
  }
  // s13, s14: the law's stress increment.
  law_->update_stress(points(), dt);
}

}  // namespace mpmx::multiscale
