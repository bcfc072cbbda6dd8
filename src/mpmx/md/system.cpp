#include "mpmx/md/system.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <istream>
#include <numeric>
#include <ostream>
#include <parallel/algorithm>

#include <fmt/format.h>

#include "mpmx/core/binary.hpp"
#include "mpmx/core/error.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/integrate.hpp"
#include "mpmx/md/stress.hpp"
#include "mpmx/md/thermal.hpp"

namespace mpmx::md {

System::System(Atoms atoms, Box box, Potential potential, SystemOptions options)
    : atoms_(std::move(atoms)), box_(box), pot_(std::move(potential)), opt_(options) {
  for (int t = 0; t < pot_.types(); ++t) mass_.push_back(pot_.mass(t));
  for (std::size_t i = 0; i < atoms_.size(); ++i)
    if (atoms_.type[i] < 0 || atoms_.type[i] >= pot_.types())
      throw InputError(fmt::format("atom {} has type {}, the potential has {} type(s)", atoms_.id[i],
                                   atoms_.type[i] + 1, pot_.types()));
  if (!(opt_.skin >= 0)) throw InputError(fmt::format("skin = {}: must be >= 0", opt_.skin));
  opt_.threads = opt_.threaded ? std::max(1, opt_.threads) : 1;  // one thread unless threaded
  nb_.tiles = opt_.threaded;
  nb_.tile_atoms = opt_.tile_atoms;
  refresh();
}

void System::refresh() {
  rebuild();
  compute_forces();
  valid_ = true;
}

void System::compact() {
  nb_.shed();
  work_ = ForceWork{};
}

std::size_t System::bytes() const {
  std::size_t b = sizeof(*this);
  for (const auto* v : {&atoms_.x, &atoms_.y, &atoms_.z, &atoms_.vx, &atoms_.vy, &atoms_.vz, &atoms_.fx, &atoms_.fy,
                        &atoms_.fz})
    b += v->capacity() * sizeof(double);
  b += atoms_.type.capacity() * sizeof(int) + atoms_.id.capacity() * sizeof(std::int64_t);
  b += mass_.capacity() * sizeof(double);
  b += nb_.bytes();
  b += (work_.fx.capacity() + work_.fy.capacity() + work_.fz.capacity() + work_.rho.capacity() +
        work_.fp.capacity() + work_.energy_atom.capacity() + work_.virial_atom.capacity()) *
       sizeof(double);
  return b;
}

void System::rebuild() {
  box_.reduce_tilt();
  const int nt = opt_.threads;
  wrap(atoms_, box_, g_, opt_.deformation == Deformation::boundary, nt);
  if (opt_.sort_atoms && atoms_.size() > 1) {
    // Spatial order (bins of half the cutoff), ties by id: deterministic.
    const double cell = std::max(0.5 * pot_.cutoff(), 1e-3);
    // Bin counts and indices clamped to [0, 2^20) before any integer arithmetic, so that
    // a box or atoms gone huge or non-finite (stopped at the next thermo row) cannot
    // overflow the key.
    constexpr double kMaxBins = 1 << 20;
    auto count = [&](double extent) { return static_cast<long>(std::clamp(extent / cell, 1.0, kMaxBins)); };
    auto index = [](double b, long n) {
      return static_cast<long>(b >= 0.0 ? std::min(b, static_cast<double>(n - 1)) : 0.0);  // NaN -> 0
    };
    const long nx = count(box_.lx), ny = count(box_.ly);
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(atoms_.size());
    std::vector<long> key(atoms_.size());
#pragma omp parallel for schedule(static) num_threads(nt) if (nt > 1)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      const long ix = index(atoms_.x[i] / box_.lx * nx, nx);
      const long iy = index(atoms_.y[i] / box_.ly * ny, ny);
      const long iz = index(atoms_.z[i] / cell, static_cast<long>(kMaxBins));
      key[i] = (iz * ny + iy) * nx + ix;
    }
    std::vector<std::size_t> order(atoms_.size());
    std::iota(order.begin(), order.end(), 0);
    // A strict total order (ids are unique): one result for any sort and thread count.
    auto before = [&](std::size_t a, std::size_t b) {
      return key[a] != key[b] ? key[a] < key[b] : atoms_.id[a] < atoms_.id[b];
    };
    if (nt > 1) {
      __gnu_parallel::sort(order.begin(), order.end(), before, __gnu_parallel::default_parallel_tag(nt));
    } else {
      std::sort(order.begin(), order.end(), before);
    }
    bool identity = true;
    for (std::size_t k = 0; k < order.size(); ++k) identity = identity && order[k] == k;
    if (!identity) atoms_.permute(order);
  }
  nb_.build(atoms_, box_, pot_.cutoff(), opt_.skin, nt);
}

void System::compute_forces(bool tally) {
  work_.per_atom = opt_.per_atom && tally;
  work_.tally = tally;
  work_.threads = opt_.threads;
  work_.reset(nb_.nall);
  const ForceSums s = pot_.compute(nb_, work_, opt_.mixed_precision);
  if (work_.tally) sums_ = s;
  if (!work_.folded) {
    nb_.fold(work_.fx);
    nb_.fold(work_.fy);
    nb_.fold(work_.fz);
    if (work_.per_atom) {
      nb_.fold(work_.energy_atom);
      nb_.fold(work_.virial_atom, 6);
    }
  }
  const std::size_t n = atoms_.size();
  std::copy_n(work_.fx.begin(), n, atoms_.fx.begin());
  std::copy_n(work_.fy.begin(), n, atoms_.fy.begin());
  std::copy_n(work_.fz.begin(), n, atoms_.fz.begin());
  if (work_.tally && !std::isfinite(sums_.energy)) check_finite();
}

void System::check_finite() const {
  for (std::size_t i = 0; i < atoms_.size(); ++i) {
    const double vals[9] = {atoms_.x[i], atoms_.y[i], atoms_.z[i], atoms_.vx[i], atoms_.vy[i],
                            atoms_.vz[i], atoms_.fx[i], atoms_.fy[i], atoms_.fz[i]};
    static const char* names[9] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz"};
    for (int c = 0; c < 9; ++c)
      if (!std::isfinite(vals[c]))
        throw RunError(fmt::format("MD step {}: atom {} has {} = {}", step_, atoms_.id[i], names[c], vals[c]));
  }
  throw RunError(fmt::format("MD step {}: potential energy is {}", step_, sums_.energy));
}

void System::thermalize(double target_K, std::uint64_t seed, std::uint64_t stream_id) {
  rng_ = RngStream(seed, stream_id);
  maxwell_velocities(atoms_, mass_, 2.0 * target_K, rng_);
}

void System::add_streaming_velocity(const Mat3& grad) {
  const Mat3 g = is_upper_triangular(grad) ? grad : upper_triangular(grad);
  const double cx = 0.5 * (box_.lx + box_.xy + box_.xz), cy = 0.5 * (box_.ly + box_.yz), cz = 0.5 * box_.lz;
  for (std::size_t i = 0; i < atoms_.size(); ++i) {
    const double x = atoms_.x[i] - cx, y = atoms_.y[i] - cy, z = atoms_.z[i] - cz;
    atoms_.vx[i] += g[0] * x + g[1] * y + g[2] * z;
    atoms_.vy[i] += g[4] * y + g[5] * z;
    atoms_.vz[i] += g[8] * z;
  }
}

namespace {

// The mean velocity of the atoms `in(id)` takes, their count and (with_temperature)
// their kinetic temperature about it, summed in atom order (the same bits on any thread
// count): a rigid body's velocity, a region's temperature.
struct GroupMotion {
  double u[3] = {0, 0, 0};
  std::int64_t n = 0;
  double temperature = 0;
};

template <class In>
GroupMotion motion_of(const Atoms& a, const std::vector<double>& mass_of, In in, bool with_temperature) {
  GroupMotion mo;
  double p[3] = {0, 0, 0}, mass = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!in(a.id[i])) continue;
    const double m = mass_of[a.type[i]];
    p[0] += m * a.vx[i], p[1] += m * a.vy[i], p[2] += m * a.vz[i], mass += m, ++mo.n;
  }
  if (mass > 0)
    for (int d = 0; d < 3; ++d) mo.u[d] = p[d] / mass;
  if (!with_temperature || mo.n < 2) return mo;
  double twice_ke = 0;  // amu A^2/ps^2
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!in(a.id[i])) continue;
    const double dx = a.vx[i] - mo.u[0], dy = a.vy[i] - mo.u[1], dz = a.vz[i] - mo.u[2];
    twice_ke += mass_of[a.type[i]] * (dx * dx + dy * dy + dz * dz);
  }
  mo.temperature = twice_ke * units::mvv2e / (3.0 * static_cast<double>(mo.n - 1) * units::boltzmann_eV_per_K);
  return mo;
}

GroupMotion motion_after(const Atoms& a, const std::vector<double>& mass_of, std::int64_t after_id) {
  return motion_of(a, mass_of, [after_id](std::int64_t id) { return id > after_id; }, true);
}

}  // namespace

double System::temperature_after(std::int64_t after_id) const { return motion_after(atoms_, mass_, after_id).temperature; }

void System::rescale_temperature(double target_K, std::int64_t after_id) {
  const GroupMotion mo = motion_after(atoms_, mass_, after_id);
  if (!(mo.temperature > 0)) return;
  const double f = std::sqrt(target_K / mo.temperature);
  const double* u = mo.u;
  for (std::size_t i = 0; i < atoms_.size(); ++i) {
    if (atoms_.id[i] <= after_id) continue;
    atoms_.vx[i] = u[0] + f * (atoms_.vx[i] - u[0]);
    atoms_.vy[i] = u[1] + f * (atoms_.vy[i] - u[1]);
    atoms_.vz[i] = u[2] + f * (atoms_.vz[i] - u[2]);
  }
}

void System::add_energy(double e) { inject_energy(atoms_, mass_, e, rng_); }

void System::advance(int nsteps, const Mat3& grad, double dt) {
  if (nsteps <= 0) return;
  if (!(dt > 0)) throw InputError(fmt::format("MD time step dt = {}: must be positive", dt));
  const Mat3 g = is_upper_triangular(grad) ? grad : upper_triangular(grad);  // eq. 5.20
  // Under boundary deformation an atom's images move at its velocity plus the gradient
  // times their shift: an atom left outside the box when the gradient changes would give
  // its image inside a jump of (g - g_) L (300 A/ps at a shock's arrival in an 18 A box).
  // It is put back in the box under the gradient it left by, as a rebuild does.
  auto outside = [&] {
    for (std::size_t i = 0; i < atoms_.size(); ++i) {
      const auto n = box_.image_of(atoms_.x[i], atoms_.y[i], atoms_.z[i]);
      if (n[0] != 0 || n[1] != 0 || n[2] != 0) return true;
    }
    return false;
  };
  if (!valid_) refresh();
  else if (!nb_.built()) rebuild();  // loaded from a list-less checkpoint: the forces are the stored ones
  else if (opt_.deformation == Deformation::boundary && g != g_ && outside()) rebuild();
  g_ = g;
  const bool affine = opt_.deformation == Deformation::affine;
  const bool deforming = std::any_of(g.begin(), g.end(), [](double v) { return v != 0.0; });
  const int nt = opt_.threads;
  kick(atoms_, mass_, dt, 0.5, nt);  // eq. 5.4
  hold_frozen();
  for (int s = 0; s < nsteps; ++s) {
    drift(atoms_, dt, g, affine && deforming, nt);  // eq. 5.5
    if (walls_.enabled) reflect(dt);
    if (deforming) box_.deform(g, dt);              // eq. 5.7
    if (nb_.needs_rebuild(atoms_, box_, nt)) rebuild();
    else nb_.update_positions(atoms_, box_, nt);
    compute_forces(s + 1 == nsteps);  // energy and virial on the last step only
    ++step_;
    time_ += dt;
    kick(atoms_, mass_, dt, s + 1 < nsteps ? 1.0 : 0.5, nt);  // eq. 5.3; last: eq. 5.6
    hold_frozen();
  }
}

void System::advance_coupled(int nsteps, double dt, Coupling& c) {
  if (nsteps <= 0) return;
  if (!(dt > 0)) throw InputError(fmt::format("MD time step dt = {}: must be positive", dt));
  if (box_.xy != 0 || box_.xz != 0 || box_.yz != 0)
    throw InputError("a thermostat or barostat needs an orthogonal box");
  if (!valid_) refresh();
  else if (!nb_.built()) rebuild();
  g_ = Mat3{};
  const int nt = opt_.threads;
  for (int s = 0; s < nsteps; ++s) {
    c.initial(*this, dt);
    kick(atoms_, mass_, dt, 0.5, nt);
    c.remap(*this, dt);
    drift(atoms_, dt, g_, false, nt);
    c.remap(*this, dt);
    if (nb_.needs_rebuild(atoms_, box_, nt)) rebuild();
    else nb_.update_positions(atoms_, box_, nt);
    compute_forces(true);
    ++step_;
    time_ += dt;
    kick(atoms_, mass_, dt, 0.5, nt);
    c.final(*this, dt);
  }
}

void System::scale_velocities(const Vec3& f) {
  for (std::size_t i = 0; i < atoms_.size(); ++i) atoms_.vx[i] *= f[0], atoms_.vy[i] *= f[1], atoms_.vz[i] *= f[2];
}

void System::dilate(const Vec3& f) {
  for (std::size_t i = 0; i < atoms_.size(); ++i) atoms_.x[i] *= f[0], atoms_.y[i] *= f[1], atoms_.z[i] *= f[2];
  box_.lx *= f[0], box_.ly *= f[1], box_.lz *= f[2];
}

Vec3 System::mvv() const {
  Vec3 k{0, 0, 0};
  for (std::size_t i = 0; i < atoms_.size(); ++i) {
    const double m = mass_[atoms_.type[i]];
    k[0] += m * atoms_.vx[i] * atoms_.vx[i], k[1] += m * atoms_.vy[i] * atoms_.vy[i], k[2] += m * atoms_.vz[i] * atoms_.vz[i];
  }
  for (auto& v : k) v *= units::mvv2e;
  return k;
}

void System::set_frozen_ids(std::int64_t max_id) {
  frozen_ids_ = max_id;
  hold_frozen();
}

void System::release_rigid(const Vec3& v) {
  rigid_free_ = true;
  for (std::size_t i = 0; i < atoms_.size(); ++i)
    if (atoms_.id[i] <= frozen_ids_) atoms_.vx[i] = v[0], atoms_.vy[i] = v[1], atoms_.vz[i] = v[2];
}

void System::hold_frozen() {
  if (frozen_ids_ <= 0) return;
  if (rigid_free_) {
    // The body's momentum over its mass, on one thread: the same bits on any count.
    const std::int64_t last = frozen_ids_;
    const GroupMotion mo = motion_of(atoms_, mass_, [last](std::int64_t id) { return id <= last; }, false);
    if (mo.n > 0) release_rigid({mo.u[0], mo.u[1], mo.u[2]});
    return;
  }
  const int nt = opt_.threads;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(atoms_.size());
#pragma omp parallel for schedule(static) num_threads(nt) if (nt > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    if (atoms_.id[i] <= frozen_ids_) atoms_.vx[i] = atoms_.vy[i] = atoms_.vz[i] = 0.0;
}

void System::reflect(double dt) {
  walls_.lo += walls_.v_lo * dt;  // the walls' positions at the new time
  walls_.hi += walls_.v_hi * dt;
  const int nt = opt_.threads;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(atoms_.size());
#pragma omp parallel for schedule(static) num_threads(nt) if (nt > 1)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (atoms_.x[i] < walls_.lo) {
      atoms_.x[i] = 2 * walls_.lo - atoms_.x[i];
      atoms_.vx[i] = 2 * walls_.v_lo - atoms_.vx[i];
    } else if (atoms_.x[i] > walls_.hi) {
      atoms_.x[i] = 2 * walls_.hi - atoms_.x[i];
      atoms_.vx[i] = 2 * walls_.v_hi - atoms_.vx[i];
    }
  }
}

Atoms System::snapshot() const {
  Atoms a = atoms_;
  wrap(a, box_, g_, opt_.deformation == Deformation::boundary);
  return a;
}

Mat3 System::stress() const {
  if (opt_.deformation == Deformation::boundary && atoms_.size() > 0) {
    return box_stress(snapshot(), mass_, sums_.virial, box_.volume());
  }
  return box_stress(atoms_, mass_, sums_.virial, box_.volume());
}

Mat3 System::stress_gpa() const {
  Mat3 s = stress();
  for (auto& v : s) v *= units::eV_per_A3_in_GPa;
  return s;
}

std::vector<Mat3> System::slab_stress_gpa(int nbins) const {
  if (!opt_.per_atom) throw RunError("binned stress needs SystemOptions::per_atom");
  auto s = slab_stress(snapshot(), mass_, work_.virial_atom, box_, nbins);
  for (auto& m : s)
    for (auto& v : m) v *= units::eV_per_A3_in_GPa;
  return s;
}

std::vector<double> System::atom_stress_gpa() const {
  if (!opt_.per_atom) throw RunError("per-atom stress needs SystemOptions::per_atom");
  std::vector<double> s = atom_stress(snapshot(), mass_, work_.virial_atom, box_.volume());
  for (auto& v : s) v *= units::eV_per_A3_in_GPa;
  return s;
}

std::vector<Mat3> System::column_stress_gpa(int nx, int ny) const {
  if (!opt_.per_atom) throw RunError("binned stress needs SystemOptions::per_atom");
  auto s = column_stress(snapshot(), mass_, work_.virial_atom, box_, nx, ny);
  for (auto& m : s)
    for (auto& v : m) v *= units::eV_per_A3_in_GPa;
  return s;
}

double System::kinetic_energy() const {
  double ke = 0;
  for (std::size_t i = 0; i < atoms_.size(); ++i)
    ke += mass_[atoms_.type[i]] *
          (atoms_.vx[i] * atoms_.vx[i] + atoms_.vy[i] * atoms_.vy[i] + atoms_.vz[i] * atoms_.vz[i]);
  return 0.5 * ke * units::mvv2e;
}

double System::thermal_kinetic_energy() const { return md::thermal_kinetic_energy(atoms_, mass_); }
double System::temperature() const { return kinetic_temperature(atoms_, mass_); }

// ---- checkpoint ----

namespace {
constexpr char kMagic[8] = {'M', 'P', 'M', 'X', 'M', 'D', '0', '2'};
template <class T>
void put(std::ostream& o, const T& v) {
  o.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void get(std::istream& i, T& v) {
  i.read(reinterpret_cast<char*>(&v), sizeof(T));
  if (!i) throw InputError("MD checkpoint is truncated");
}
template <class T>
void put_vec(std::ostream& o, const std::vector<T>& v) {
  o.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}
template <class T>
void get_vec(std::istream& i, std::vector<T>& v, std::size_t n) {
  v.resize(n);
  i.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T)));
  if (!i) throw InputError("MD checkpoint is truncated");
}
}  // namespace

void System::save(std::ostream& o) const {
  o.write(kMagic, 8);
  const std::uint64_t n = atoms_.size();
  put(o, n);
  put(o, box_);
  put(o, step_);
  put(o, time_);
  put(o, g_);
  put(o, rng_.state());
  put(o, walls_);
  for (auto* v : {&atoms_.x, &atoms_.y, &atoms_.z, &atoms_.vx, &atoms_.vy, &atoms_.vz})
    put_vec(o, *v);
  put_vec(o, atoms_.type);
  put_vec(o, atoms_.id);
  // The neighbour list's build state, so a restart rebuilds the very same list (same
  // pairs, same order) and continues bit-for-bit; a compacted box keeps its forces and
  // tallies instead (its next advance builds a list afresh).
  const bool compacted = valid_ && !nb_.built();
  const std::uint8_t built = compacted ? 2 : nb_.built() && nb_.nlocal == static_cast<int>(n);
  put(o, built);
  put(o, neighbor_builds());
  if (compacted) {
    for (auto* v : {&atoms_.fx, &atoms_.fy, &atoms_.fz}) put_vec(o, *v);
    put(o, sums_);
  } else if (built) {
    put(o, nb_.box_at_build());
    put_vec(o, nb_.x_at_build());
    put_vec(o, nb_.y_at_build());
    put_vec(o, nb_.z_at_build());
  }
}

System System::load(std::istream& in, Potential potential, SystemOptions options) {
  char magic[8];
  in.read(magic, 8);
  if (!in || std::memcmp(magic, kMagic, 8) != 0) throw InputError("not an mpmx MD checkpoint");
  // 6 coordinates, a type and an id per atom at least: a damaged count is refused here.
  const std::uint64_t n = read_count(in, 6 * sizeof(double) + sizeof(int), "MD atoms");
  if (n == 0) throw InputError("MD checkpoint: a box of no atoms");
  Box box;
  get(in, box);
  // Bounds no saved run comes near, which keep the neighbour list's image counts (at most
  // 127 a side) and its integer arithmetic in range for whatever the file says.
  const double reach = potential.cutoff() + options.skin;
  auto box_ok = [&](const Box& b) {
    for (double v : {b.lx, b.ly, b.lz})
      if (!(v >= reach / 64 && v <= 1e6 * reach)) return false;
    return std::abs(b.xy) <= 64 * b.lx && std::abs(b.xz) <= 64 * b.lx && std::abs(b.yz) <= 64 * b.ly;
  };
  auto inside = [](const Box& b, double x, double y, double z) {
    return std::abs(x) <= 2 * (b.lx + std::abs(b.xy) + std::abs(b.xz)) && std::abs(y) <= 2 * (b.ly + std::abs(b.yz)) &&
           std::abs(z) <= 2 * b.lz;
  };
  if (!box_ok(box))
    throw InputError(fmt::format("MD checkpoint: box {} x {} x {} (tilts {}, {}, {}) is not one a run makes for a "
                                 "reach of {} A",
                                 box.lx, box.ly, box.lz, box.xy, box.xz, box.yz, reach));
  std::int64_t step;
  double time;
  Mat3 g;
  std::array<std::uint64_t, 4> rng;
  get(in, step);
  get(in, time);
  get(in, g);
  get(in, rng);
  Walls walls;
  get(in, walls);
  Atoms a;
  for (auto* v : {&a.x, &a.y, &a.z, &a.vx, &a.vy, &a.vz}) get_vec(in, *v, n);
  get_vec(in, a.type, n);
  get_vec(in, a.id, n);
  const int types = potential.types();
  for (const auto t : a.type)
    if (t < 0 || t >= types)
      throw InputError(fmt::format("MD checkpoint: atom type {} outside the potential's 0..{}", t, types - 1));
  for (const auto* v : {&a.vx, &a.vy, &a.vz})
    for (double x : *v)
      if (!std::isfinite(x)) throw InputError("MD checkpoint: a non-finite atom velocity");
  for (std::size_t i = 0; i < n; ++i)
    if (!inside(box, a.x[i], a.y[i], a.z[i]))
      throw InputError(fmt::format("MD checkpoint: atom {} at ({}, {}, {}) lies far outside its box", i, a.x[i],
                                   a.y[i], a.z[i]));
  a.fx.assign(n, 0.0);
  a.fy.assign(n, 0.0);
  a.fz.assign(n, 0.0);
  std::uint8_t built;
  std::int64_t builds;
  get(in, built);
  get(in, builds);
  System s(a, box, std::move(potential), options);
  s.atoms_ = std::move(a);
  s.box_ = box;
  s.step_ = step;
  s.time_ = time;
  s.g_ = g;
  s.rng_.set_state(rng);
  s.walls_ = walls;
  if (built == 2) {  // compacted: the stored forces and tallies
    for (auto* v : {&s.atoms_.fx, &s.atoms_.fy, &s.atoms_.fz}) get_vec(in, *v, n);
    get(in, s.sums_);
    for (const auto* v : {&s.atoms_.fx, &s.atoms_.fy, &s.atoms_.fz})
      for (double x : *v)
        if (!std::isfinite(x)) throw InputError("MD checkpoint: a non-finite atom force");
    s.nb_ = Neighbors{};  // the constructor's list is of its own copy of the atoms
    s.work_ = ForceWork{};
    s.builds_ = builds;
    s.valid_ = true;
    return s;
  }
  if (!built) {
    s.refresh();
    return s;
  }
  // Rebuild the list from the positions it was built from, then move to the saved ones:
  // the forces are those the uninterrupted run holds.
  Atoms at_build = s.atoms_;
  Box box_at_build;
  get(in, box_at_build);
  if (!box_ok(box_at_build)) throw InputError("MD checkpoint: the neighbour list's box is not valid");
  get_vec(in, at_build.x, n);
  get_vec(in, at_build.y, n);
  get_vec(in, at_build.z, n);
  for (std::size_t i = 0; i < n; ++i)
    if (!inside(box_at_build, at_build.x[i], at_build.y[i], at_build.z[i]))
      throw InputError(fmt::format("MD checkpoint: the neighbour list's atom {} lies far outside its box", i));
  s.nb_.build(at_build, box_at_build, s.pot_.cutoff(), s.opt_.skin, s.opt_.threads);
  s.nb_.builds = builds;
  s.nb_.update_positions(s.atoms_, s.box_);
  s.compute_forces();
  s.valid_ = true;
  return s;
}

}  // namespace mpmx::md
