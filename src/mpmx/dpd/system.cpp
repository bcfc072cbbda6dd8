#include "mpmx/dpd/system.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/dpd/shardlow.hpp"

namespace mpmx::dpd {

System::System(Particles particles, Domain domain, PairPotential potential, DpdParams params, SystemOptions options,
               std::vector<RigidGroup> groups)
    : p_(std::move(particles)),
      d_(domain),
      pot_(std::move(potential)),
      par_(params),
      opt_(options),
      groups_(std::move(groups)) {
  const std::size_t n = p_.size();
  if (p_.mass.size() != n || p_.u.size() != n || p_.group.size() != n || p_.vx.size() != n || p_.fx.size() != n)
    throw InputError("dpd: particle arrays of different lengths");
  if (!(d_.box.lx > 0 && d_.box.ly > 0 && d_.box.lz > 0) || d_.box.xy != 0 || d_.box.xz != 0 || d_.box.yz != 0)
    throw InputError(fmt::format("dpd: the box {} x {} x {} must be orthogonal with positive edges", d_.box.lx,
                                 d_.box.ly, d_.box.lz));
  if (!(opt_.skin >= 0)) throw InputError(fmt::format("dpd: skin = {}: must be >= 0", opt_.skin));
  if (opt_.threads < 1) throw InputError(fmt::format("dpd: threads = {}: must be >= 1", opt_.threads));
  list_.nb.tile_atoms = opt_.tile_particles;
  if (!(par_.gamma >= 0)) throw InputError(fmt::format("dpd: gamma = {}: must be >= 0", par_.gamma));
  if (par_.gamma > 0 && !(par_.cutoff > 0)) throw InputError("dpd: the dissipative cutoff must be positive");
  if (par_.energy_conserving && par_.integrator != Integrator::shardlow)
    throw InputError("dpd: DPDE (energy-conserving DPD) needs the shardlow integrator");
  if (par_.energy_conserving && !(par_.heat_capacity > 0))
    throw InputError("dpd: DPDE needs a positive heat capacity per particle");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(p_.mass[i] > 0))
      throw InputError(fmt::format("dpd: particle {} has mass {}: must be positive", p_.id[i], p_.mass[i]));
    const int g = p_.group[i];
    if (g != kMobile && (g < 0 || g >= static_cast<int>(groups_.size())))
      throw InputError(fmt::format("dpd: particle {} is in rigid group {}, there are {}", p_.id[i], g,
                                   groups_.size()));
    if (g != kMobile && !groups_[g].external) {
      p_.vx[i] = groups_[g].velocity[0];
      p_.vy[i] = groups_[g].velocity[1];
      p_.vz[i] = groups_[g].velocity[2];
    }
  }
  // The conservative forces and energy of the start; the random forces of the velocity
  // Verlet integrator need dt and come with the first step.
  rebuild();
  sums_ = compute_pair_forces(pot_, list_, p_, nullptr, buf_, opt_.threads);
  dt_ = 0;
  valid_ = true;
}

double System::neighbor_cutoff() const {
  return std::max(cutoff(pot_), par_.gamma > 0 ? par_.cutoff : 0.0);
}

void System::refresh(double dt) {
  rebuild();
  compute_forces(dt);
  valid_ = true;
}

void System::rebuild() {
  const std::size_t n = p_.size();
  for (std::size_t i = 0; i < n; ++i) {
    p_.x[i] = d_.wrap(0, p_.x[i]);
    p_.y[i] = d_.wrap(1, p_.y[i]);
    p_.z[i] = d_.wrap(2, p_.z[i]);
  }
  if (opt_.sort && n > 1) {
    // Spatial order (bins of half the cutoff), ties by id: deterministic.
    const double cell = std::max(0.5 * neighbor_cutoff(), 1e-3);
    const std::vector<double>* c[3] = {&p_.x, &p_.y, &p_.z};
    double lo[3];
    long nb[3];
    for (int d = 0; d < 3; ++d) {
      double a = 0, b = d_.length(d);
      if (!d_.periodic[d]) {
        const auto [mn, mx] = std::minmax_element(c[d]->begin(), c[d]->end());
        a = *mn, b = *mx;
      }
      lo[d] = a;
      nb[d] = std::clamp(static_cast<long>((b - a) / cell), 1L, 1L << 20);
    }
    // x fastest; with the Shardlow sweep, the longest axis slowest: the sweep's slabs
    // across it (pair_list.hpp) are then runs of consecutive particles, so threads on
    // different slabs write to different cache lines (1.74x on two threads before,
    // 1.91x after; the pair forces alone run 1% faster in the plain order).
    std::array<int, 3> axes{0, 1, 2};  // fastest first
    if (par_.integrator == Integrator::shardlow && par_.gamma > 0)
      std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return nb[a] < nb[b]; });
    std::vector<long> key(n);
    for (std::size_t i = 0; i < n; ++i) {
      long k = 0;
      for (int t = 2; t >= 0; --t) {
        const int d = axes[t];
        k = k * nb[d] + std::clamp(static_cast<long>(((*c[d])[i] - lo[d]) / cell), 0L, nb[d] - 1);
      }
      key[i] = k;
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return key[a] != key[b] ? key[a] < key[b] : p_.id[a] < p_.id[b]; });
    bool identity = true;
    for (std::size_t k = 0; k < n; ++k) identity = identity && order[k] == k;
    if (!identity) p_.permute(order);
  }
  const bool sweep = par_.integrator == Integrator::shardlow && par_.gamma > 0;
  list_.build(p_, d_, neighbor_cutoff(), opt_.skin, sweep, opt_.threads);
  mark_external();
}

void System::mark_external() {
  // The points of external groups (a continuum) do not interact with each other: the mask
  // follows the particle order, which only a rebuild changes (make_external asks for one).
  bool external = false;
  for (const auto& g : groups_) external = external || g.external;
  no_pair_.clear();
  if (external) {
    no_pair_.resize(p_.size());
    for (std::size_t i = 0; i < p_.size(); ++i) no_pair_[i] = p_.group[i] != kMobile && groups_[p_.group[i]].external;
  }
}

void System::compute_forces(double dt, bool tally) {
  dt_ = dt;
  StochasticForces st;
  const bool stochastic = par_.integrator == Integrator::velocity_verlet && par_.gamma > 0;
  if (stochastic) {
    st.gamma = par_.gamma;
    st.temperature = par_.temperature;
    st.cutoff = par_.cutoff;
    st.dt = dt;
    st.seed = par_.seed;
    st.step = step_;
  }
  const particles::ForceSums s = compute_pair_forces(pot_, list_, p_, stochastic ? &st : nullptr, buf_, opt_.threads, tally,
                                              no_pair_.empty() ? nullptr : no_pair_.data());
  if (tally) sums_ = s;
}

void System::advance(int nsteps, double dt, const Berendsen* thermostat) {
  if (nsteps <= 0) return;
  if (!(dt > 0)) throw InputError(fmt::format("dpd: time step dt = {}: must be positive", dt));
  const bool vv_stochastic = par_.integrator == Integrator::velocity_verlet && par_.gamma > 0;
  if (!valid_ || (vv_stochastic && dt != dt_)) refresh(dt);  // dt_ = 0 after construction
  const std::size_t n = p_.size();
  const bool shardlow = par_.integrator == Integrator::shardlow;
  SweepParams sp;
  sp.gamma = par_.gamma;
  sp.cutoff = par_.cutoff;
  sp.dt = dt;
  sp.energy_conserving = par_.energy_conserving;
  sp.temperature = par_.temperature;
  sp.heat_capacity = par_.heat_capacity;
  sp.seed = par_.seed;
  const double half = 0.5 * dt * units::ftm2v;
  const int threads = opt_.threads;
  auto kick = [&] {
    kick_free_groups(0.5 * dt);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (std::size_t i = 0; i < n; ++i) {
      if (p_.group[i] != kMobile) continue;
      const double h = half / p_.mass[i];
      p_.vx[i] += h * p_.fx[i];
      p_.vy[i] += h * p_.fy[i];
      p_.vz[i] += h * p_.fz[i];
    }
  };
  for (int s = 0; s < nsteps; ++s) {
    if (shardlow) {
      sp.step = step_;
      shardlow_sweep(list_, p_, sp, sweep_work_, opt_.threads);
    }
    if (mover_) {
      kick_free_groups(dt);  // symplectic Euler from the forces at x^n, as the grid's particles
      mover_->move(p_, dt);
    } else {
      kick();
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
      for (std::size_t i = 0; i < n; ++i) {
        p_.x[i] += dt * p_.vx[i];
        p_.y[i] += dt * p_.vy[i];
        p_.z[i] += dt * p_.vz[i];
      }
    }
    ++step_;
    time_ += dt;
    if (list_.needs_rebuild(p_, d_, opt_.threads)) rebuild();
    else list_.update_positions(p_, d_, opt_.threads);
    compute_forces(dt, s + 1 == nsteps);  // energy and virial on the last step only
    if (!mover_) kick();
    if (thermostat) berendsen_rescale(p_, *thermostat, dt, par_.energy_conserving ? par_.heat_capacity : 0.0);
  }
  if (!std::isfinite(sums_.energy)) check_finite();
  if (!std::isfinite(kinetic_energy() + internal_energy())) check_finite();
}

void System::check_finite() const {
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const double vals[10] = {p_.x[i], p_.y[i], p_.z[i], p_.vx[i], p_.vy[i], p_.vz[i], p_.fx[i], p_.fy[i], p_.fz[i], p_.u[i]};
    static const char* names[10] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz", "u"};
    for (int c = 0; c < 10; ++c)
      if (!std::isfinite(vals[c]))
        throw RunError(fmt::format("DPD step {}: particle {} has {} = {}", step_, p_.id[i], names[c], vals[c]));
  }
  throw RunError(fmt::format("DPD step {}: conservative energy is {}", step_, sums_.energy));
}

double System::kinetic_energy() const {
  double k = 0;
  for (std::size_t i = 0; i < p_.size(); ++i)
    k += p_.mass[i] * (p_.vx[i] * p_.vx[i] + p_.vy[i] * p_.vy[i] + p_.vz[i] * p_.vz[i]);
  return 0.5 * k * units::mvv2e;
}

double System::internal_energy() const {
  double s = 0;
  for (double v : p_.u) s += v;
  return s;
}

double System::internal_temperature() const {
  if (!(par_.heat_capacity > 0) || p_.size() == 0) return 0.0;
  return internal_energy() / (static_cast<double>(p_.size()) * par_.heat_capacity);
}

particles::Vec3 System::momentum() const {
  particles::Vec3 m{};
  for (std::size_t i = 0; i < p_.size(); ++i) {
    m[0] += p_.mass[i] * p_.vx[i];
    m[1] += p_.mass[i] * p_.vy[i];
    m[2] += p_.mass[i] * p_.vz[i];
  }
  return m;
}

particles::Mat3 System::stress_gpa() const {
  double k[6] = {};
  for (std::size_t i = 0; i < p_.size(); ++i) {
    const double m = p_.mass[i];
    k[0] += m * p_.vx[i] * p_.vx[i], k[1] += m * p_.vy[i] * p_.vy[i], k[2] += m * p_.vz[i] * p_.vz[i];
    k[3] += m * p_.vx[i] * p_.vy[i], k[4] += m * p_.vx[i] * p_.vz[i], k[5] += m * p_.vy[i] * p_.vz[i];
  }
  const double f = -units::eV_per_A3_in_GPa / d_.volume();
  double s[6];
  for (int c = 0; c < 6; ++c) s[c] = f * (k[c] * units::mvv2e + sums_.virial[c]);
  return {s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2]};
}

double System::pressure_gpa() const {
  const particles::Mat3 s = stress_gpa();
  return -(s[0] + s[4] + s[8]) / 3.0;
}

void System::set_group_velocity(int g, const particles::Vec3& v) {
  if (g < 0 || g >= static_cast<int>(groups_.size()))
    throw InputError(fmt::format("dpd: rigid group {}: there are {}", g, groups_.size()));
  if (groups_[g].external)
    throw InputError(fmt::format("dpd: group \"{}\" is moved by the mover, not at a set velocity", groups_[g].name));
  groups_[g].velocity = v;
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (p_.group[i] == g) p_.vx[i] = v[0], p_.vy[i] = v[1], p_.vz[i] = v[2];
}

void System::release_group(int g) {
  if (g < 0 || g >= static_cast<int>(groups_.size()) || groups_[g].external)
    throw InputError(fmt::format("dpd: group {} is not a rigid group", g));
  double m = 0;
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (p_.group[i] == g) m += p_.mass[i];
  if (!(m > 0)) throw InputError(fmt::format("dpd: rigid group \"{}\" holds no particle", groups_[g].name));
  groups_[g].free = true;
  groups_[g].mass = m;
}

void System::kick_free_groups(double dt) {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    if (!groups_[g].free) continue;
    const particles::Vec3 f = group_force(static_cast<int>(g));
    particles::Vec3 v = groups_[g].velocity;
    for (int d = 0; d < 3; ++d) v[d] += dt * units::ftm2v * f[d] / groups_[g].mass;
    set_group_velocity(static_cast<int>(g), v);
  }
}

int System::group_index(std::string_view name) const {
  for (std::size_t g = 0; g < groups_.size(); ++g)
    if (groups_[g].name == name) return static_cast<int>(g);
  return -1;
}

void System::make_external(int g, const std::vector<std::int64_t>& ids) {
  if (g < 0 || g >= static_cast<int>(groups_.size()) || !groups_[g].external)
    throw InputError(fmt::format("dpd: group {} is not an external group", g));
  std::vector<std::int64_t> sorted = ids;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < p_.size(); ++i) {
    if (p_.group[i] != kMobile || !std::binary_search(sorted.begin(), sorted.end(), p_.id[i])) continue;
    p_.group[i] = g;
    p_.type[i] = 1;  // type 2 in the dump
    p_.vx[i] = p_.vy[i] = p_.vz[i] = 0.0;  // the continuum's thermal motion is in its law
  }
  valid_ = false;
}

particles::Vec3 System::group_force(int g) const {
  particles::Vec3 f{};
  for (std::size_t i = 0; i < p_.size(); ++i)
    if (p_.group[i] == g) f[0] += p_.fx[i], f[1] += p_.fy[i], f[2] += p_.fz[i];
  return f;
}

}  // namespace mpmx::dpd
