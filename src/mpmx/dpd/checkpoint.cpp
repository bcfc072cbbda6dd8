// dpd::System::save and load: the state a resumed DPD run needs to continue bit-for-bit.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <istream>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/binary.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/dpd/system.hpp"

namespace mpmx::dpd {

namespace {

constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'D', 'P', 'D', '1'};

constexpr const char* kState = "DPD state";

void finite(const std::vector<double>& v, const char* what) {
  for (double x : v)
    if (!std::isfinite(x)) throw InputError(fmt::format("the DPD state holds a non-finite {}", what));
}

}  // namespace

void System::save(std::ostream& o) const {
  o.write(kMagic, 8);
  write_raw<std::uint64_t>(o, p_.size());
  write_raw(o, step_);
  write_raw(o, time_);
  write_raw(o, dt_);
  write_raw(o, sums_);
  write_raw<std::uint64_t>(o, groups_.size());
  for (const RigidGroup& g : groups_) {
    write_raw(o, g.velocity);
    write_raw<std::uint8_t>(o, g.free);
    write_raw(o, g.mass);
  }
  for (auto* v : {&p_.x, &p_.y, &p_.z, &p_.vx, &p_.vy, &p_.vz, &p_.fx, &p_.fy, &p_.fz, &p_.mass, &p_.u}) write_values(o, *v);
  write_values(o, p_.type);
  write_values(o, p_.group);
  write_values(o, p_.id);
  write_raw(o, list_.nb.builds);
  write_values(o, list_.nb.x_at_build());
  write_values(o, list_.nb.y_at_build());
  write_values(o, list_.nb.z_at_build());
}

void System::load(std::istream& in) {
  char magic[8] = {};
  in.read(magic, 8);
  if (!in || std::memcmp(magic, kMagic, 8) != 0) throw InputError("not the state of a DPD system");
  // 14 numbers, 2 ints and an id per particle at least: a damaged count is refused here.
  const std::uint64_t n = read_count(in, 14 * sizeof(double) + 2 * sizeof(int) + sizeof(std::int64_t), "particle");
  if (n != p_.size()) throw InputError(fmt::format("{} particles, the deck makes {}", n, p_.size()));
  const auto step = read_raw<std::int64_t>(in, kState);
  const auto time = read_raw<double>(in, kState), dt = read_raw<double>(in, kState);
  const auto sums = read_raw<particles::ForceSums>(in, kState);
  if (step < 0 || !std::isfinite(time) || !std::isfinite(dt))
    throw InputError(fmt::format("step {}, time {}, dt {}: not a run's", step, time, dt));
  const auto groups = read_count(in, sizeof(particles::Vec3) + 1 + sizeof(double), "group");
  if (groups != groups_.size())
    throw InputError(fmt::format("{} rigid groups, the deck makes {}", groups, groups_.size()));
  std::vector<RigidGroup> g = groups_;
  for (RigidGroup& k : g) {
    k.velocity = read_raw<particles::Vec3>(in, kState);
    k.free = read_raw<std::uint8_t>(in, kState) != 0;
    k.mass = read_raw<double>(in, kState);
    if (!std::isfinite(k.velocity[0] + k.velocity[1] + k.velocity[2]) || !(k.mass >= 0) || (k.free && !(k.mass > 0)))
      throw InputError(fmt::format("rigid group \"{}\": a velocity or mass no run makes", k.name));
  }
  Particles p = p_;
  for (auto* v : {&p.x, &p.y, &p.z, &p.vx, &p.vy, &p.vz, &p.fx, &p.fy, &p.fz, &p.mass, &p.u}) {
    read_values(in, *v, n, kState);
    finite(*v, "particle value");
  }
  read_values(in, p.type, n, kState);
  read_values(in, p.group, n, kState);
  read_values(in, p.id, n, kState);
  const auto builds = read_raw<std::int64_t>(in, kState);
  Particles at_build = p;
  read_values(in, at_build.x, n, kState);
  read_values(in, at_build.y, n, kState);
  read_values(in, at_build.z, n, kState);
  for (const auto* v : {&at_build.x, &at_build.y, &at_build.z}) finite(*v, "neighbour-list position");
  // The same particles as the deck's (ids, types and masses), in the saved order.
  std::vector<std::size_t> mine(n), saved(n);
  for (std::size_t i = 0; i < n; ++i) mine[i] = saved[i] = i;
  std::sort(mine.begin(), mine.end(), [&](auto a, auto b) { return p_.id[a] < p_.id[b]; });
  std::sort(saved.begin(), saved.end(), [&](auto a, auto b) { return p.id[a] < p.id[b]; });
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = mine[k], b = saved[k];
    if (p_.id[a] != p.id[b] || (p.group[b] == kMobile && p_.type[a] != p.type[b]) || !(p.mass[b] > 0))
      throw InputError(fmt::format("particle {} is not one of the deck's", p.id[b]));
    if (p.group[b] != kMobile && (p.group[b] < 0 || p.group[b] >= static_cast<int>(groups)))
      throw InputError(fmt::format("particle {} is in rigid group {}, there are {}", p.id[b], p.group[b], groups));
  }
  p_ = std::move(p);
  groups_ = std::move(g);
  step_ = step, time_ = time, dt_ = dt, sums_ = sums;
  const bool sweep = par_.integrator == Integrator::shardlow && par_.gamma > 0;
  list_.build(at_build, d_, neighbor_cutoff(), opt_.skin, sweep, opt_.threads);
  list_.nb.builds = builds;
  list_.update_positions(p_, d_, opt_.threads);
  mark_external();
  valid_ = true;
}

}  // namespace mpmx::dpd
