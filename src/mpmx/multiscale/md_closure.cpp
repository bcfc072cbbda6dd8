#include "mpmx/multiscale/md_closure.hpp"

#include <chrono>
#include <stdexcept>
#include <cmath>
#include <numeric>
#include <algorithm>
#include <cstdlib>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <type_traits>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/binary.hpp"
#include "mpmx/core/interrupt.hpp"
#include "mpmx/core/units.hpp"
#include "mpmx/md/lammps_dump.hpp"
#include "mpmx/md/nose_hoover.hpp"
#include "mpmx/particles/lattice.hpp"

namespace mpmx::multiscale {

namespace {

// Continuum mass unit in amu: stress * time^2 * length.
double mass_unit_amu(const units::UnitSystem& u) {
  const double length_m = u.length_A * units::angstrom_in_m, time_s = u.time_ps * units::ps_in_s;
  return u.stress_GPa * units::GPa_in_Pa * time_s * time_s * length_m / units::amu_in_kg;
}

MdClosureProperties properties(const md::FccEquilibrium& eq, const units::UnitSystem& u) {
  MdClosureProperties r;
  r.equilibrium = eq;
  r.density = eq.density_amu_per_A3 / mass_unit_amu(u) * std::pow(u.length_A, 3);
  r.modulus = eq.c11_gpa / u.stress_GPa;
  r.c12 = eq.c12_gpa / u.stress_GPa;
  r.c44 = eq.c44_gpa / u.stress_GPa;
  r.sound_speed = std::sqrt(r.modulus / r.density);
  return r;
}

// The record a group's box returns to every rank: its stress (GPa), its box, its
// neighbour-list builds, eq. 7.11's energy in and short, its temperature, what it owes
// and its energy per unit mass.
constexpr int kGroupRecord = 21;

// A box's energy (potential plus kinetic about its mean velocity) per unit mass, eV/amu.
double specific_energy(const md::System& box) {
  double mass = 0.0;
  for (const int t : box.atoms().type) mass += box.type_mass()[static_cast<std::size_t>(t)];
  return (box.potential_energy() + box.thermal_kinetic_energy()) / mass;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "rank r: " before a message where there are several ranks.
std::string where() { return ranks::size() > 1 ? fmt::format("rank {}: ", ranks::rank()) : ""; }

using Mat3d = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

Mat3d as_matrix(const md::Mat3& m) { return Eigen::Map<const Mat3d>(m.data()); }
md::Mat3 as_array(const Mat3d& m) {
  md::Mat3 r;
  Eigen::Map<Mat3d>(r.data()) = m;
  return r;
}

// The Cayley rotation of a spin W over dt: (I - W dt/2)^-1 (I + W dt/2), orthogonal to
// round-off.
Mat3d cayley(const Mat3d& W, double dt) {
  const Mat3d I = Mat3d::Identity();
  return (I - 0.5 * dt * W).inverse() * (I + 0.5 * dt * W);
}

template <typename T>
void write_raw(std::ostream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}
template <typename T>
void read_raw(std::istream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof v);
}

// fcc along the axes by the scan it always had (the seed's numbers bit for bit); any
// other crystal by lattice_equilibrium's, its constants in the box frame.
md::CrystalEquilibrium equilibrium_of(const md::Potential& pot, const particles::LatticeSpec& lattice) {
  return lattice.plain_fcc() ? md::fcc_equilibrium(pot) : md::lattice_equilibrium(pot, lattice);
}

}  // namespace

MdClosureProperties md_closure_properties(const md::PotentialSpec& spec, const units::UnitSystem& u,
                                          const particles::LatticeSpec& lattice) {
  const md::Potential pot(spec);
  MdClosureProperties r = properties(equilibrium_of(pot, lattice), u);
  r.cutoff = pot.cutoff();
  return r;
}

std::shared_ptr<const md::CompressionModuli> md_closure_stiffness(const md::Potential& pot,
                                                                  const particles::LatticeSpec& lattice,
                                                                  double a0) {
  particles::LatticeSpec at = lattice;
  at.constant = a0;
  return std::make_shared<const md::CompressionModuli>(md::compression_moduli(pot, at));
}

int MdClosureConfig::atoms_per_point() const {
  if (lattice.plain_fcc()) return 4 * cells * cells * cells;
  particles::LatticeSpec unit = lattice;
  unit.constant = 1.0;  // the tile's atoms do not depend on the constant
  return static_cast<int>(particles::lattice_tile_atoms(unit)) * cells * cells * cells;
}

PreparedLattice prepare_npt(const md::Potential& pot, const MdClosureConfig& c, double a0) {
  particles::LatticeSpec spec = c.lattice;
  spec.constant = a0;
  md::SystemOptions o;
  o.skin = c.skin;
  o.threads = 1;  // one box: the same numbers on any thread count
  md::System box(particles::oriented_crystal(spec, {c.cells, c.cells, c.cells}), pot, o);
  const double v0 = box.box().volume();
  // Its own random stream: the points' boxes take streams 0, 1, ... (their indices).
  box.thermalize(c.temperature, c.seed, std::numeric_limits<std::uint64_t>::max());
  md::NoseHooverOptions nh;
  nh.thermostat = true, nh.temperature = c.temperature, nh.t_damp = 0.1;
  nh.barostat = true, nh.isotropic = true, nh.pressure = {0.0, 0.0, 0.0}, nh.p_damp = 1.0;
  md::NoseHoover coupling(nh, box);
  const std::int64_t half = c.prepare_steps / 2, rest = c.prepare_steps - half;
  // In chunks of 1000 steps, so that Ctrl-C stops it (initialize then ends the run).
  for (std::int64_t done = 0; done < half && !InterruptGuard::interrupted();) {
    const int chunk = static_cast<int>(std::min<std::int64_t>(half - done, 1000));
    box.advance_coupled(chunk, c.dt, coupling);
    done += chunk;
  }
  double volume = 0.0, pressure = 0.0, temperature = 0.0;
  for (std::int64_t k = 0; k < rest; ++k) {  // the second half, sampled every step
    if (k % 1000 == 0 && InterruptGuard::interrupted()) return PreparedLattice{a0, 0.0, 0.0};
    box.advance_coupled(1, c.dt, coupling);
    const md::Mat3 s = box.stress_gpa();
    volume += box.box().volume(), pressure -= (s[0] + s[4] + s[8]) / 3.0, temperature += box.temperature();
  }
  const double n = static_cast<double>(rest);  // >= 1: the deck asks for 2 steps or more
  PreparedLattice r;
  r.lattice_constant = a0 * std::cbrt(volume / n / v0);
  r.pressure_gpa = pressure / n;
  r.temperature = temperature / n;
  if (!std::isfinite(r.lattice_constant) || !(r.lattice_constant > 0))
    throw RunError(fmt::format("the NPT preparation of the MD boxes ({} steps at {} K) did not settle: its mean "
                               "volume is {}; try a smaller material.md.dt",
                               c.prepare_steps, c.temperature, volume / n));
  return r;
}

int MdClosureConfig::md_steps(double dt_continuum) const {
  const double steps = dt_continuum * units.time_ps / dt;
  // A count past an int is not a step the boxes can take (they advance an int at a time).
  if (!(steps < std::numeric_limits<int>::max())) return 0;
  const long k = std::lround(steps);
  return k >= 1 && std::abs(steps - k) <= 1e-6 * steps ? static_cast<int>(k) : 0;
}

template <int Dim>
MdClosure<Dim>::MdClosure(const MdClosureConfig& config)
    : cfg_(config), pot_(config.potential), props_(properties(equilibrium_of(pot_, config.lattice), config.units)),
      batch_(config.threads) {
  if (!cfg_.stiffness) cfg_.stiffness = md_closure_stiffness(pot_, cfg_.lattice, props_.equilibrium.lattice_constant);
}

template <int Dim>
md::SystemOptions MdClosure<Dim>::box_options() const {
  md::SystemOptions o;
  o.skin = cfg_.skin;
  o.mixed_precision = cfg_.mixed_precision;
  o.deformation = cfg_.deformation;
  return o;
}

template <int Dim>
double MdClosure<Dim>::audit_rel_rms() const {
  return audit_samples_ > 0 && audit_s2_ > 0 ? std::sqrt(audit_d2_ / audit_s2_) : std::nan("");
}

template <int Dim>
void MdClosure<Dim>::spread_groups(const std::vector<double>& cost) {
  const Spread s = Spread::balanced(cost);
  owner_.assign(cost.size(), 0);
  for (int r = 0; r < s.ranks(); ++r)
    for (std::size_t g = s.start(r); g < s.start(r + 1); ++g) owner_[g] = r;
}

template <int Dim>
void MdClosure<Dim>::initialize(const Points<Dim>& p) {
  const std::size_t n = p.size();
  if (const char* v = std::getenv("MPMX_TEST_NAN_POINT")) nan_point_ = std::strtoull(v, nullptr, 10);
  groups_ = BoxGroups(std::vector<double>(p.strain[0], p.strain[0] + n), cfg_.share);
  const std::size_t G = groups_.groups();
  spread_groups(std::vector<double>(G, 1.0));
  const auto t0 = std::chrono::steady_clock::now();
  // prepare = npt: the one box relaxed at (T, 0 GPa) first, on every rank alike (one
  // thread: the same numbers everywhere), whose mean lattice constant all boxes take.
  std::optional<ranks::Failure> failed;
  prepared_.reset();
  if (cfg_.prepare == BoxPrepare::npt && cfg_.prepared) {
    prepared_ = cfg_.prepared;  // run when the deck was read
  } else if (cfg_.prepare == BoxPrepare::npt) {
    try {
      prepared_ = prepare_npt(pot_, cfg_, props_.equilibrium.lattice_constant);
    } catch (const std::exception&) {
      failed = ranks::current_failure();
    }
  }
  particles::LatticeSpec spec = cfg_.lattice;
  spec.constant = box_lattice_constant();
  // Each group's box built on the threads (section 6.2) from its first point's strain
  // and random stream: one group per point gives every point the box it had alone.
  std::vector<std::size_t> todo;
  for (std::size_t g = 0; g < G; ++g)
    if (mine(g)) todo.push_back(g);
  boxes_.clear();
  boxes_.resize(G);
  if (!failed) try {
    batch_.for_each(todo.size(), [&](std::size_t k) {
      const std::size_t g = todo[k], q = groups_.members(g).front();
      if (InterruptGuard::interrupted()) return;  // Ctrl-C: the boxes left are not built
      try {
        md::System box(particles::oriented_crystal(spec, {cfg_.cells, cfg_.cells, cfg_.cells}, p.strain[0][q]), pot_,
                       box_options());
        if (cfg_.temperature > 0) box.thermalize(cfg_.temperature, cfg_.seed, q);
        box.advance(static_cast<int>(cfg_.relax_steps), cfg_.dt);  // zero strain rate
        box.compact();
        boxes_[g] = std::make_unique<md::System>(std::move(box));
      } catch (const std::exception&) {  // the same kind of error, naming the point
        ranks::Failure f = ranks::current_failure();
        f.message = fmt::format("the MD box of material point {}: {}", q, f.message);
        ranks::raise(f);
      }
    });
  } catch (const std::exception&) {
    failed = ranks::current_failure();
    failed->message = fmt::format("{}building {}", where(), failed->message);
  }
  if (failed) {
    boxes_.clear();
    boxes_.resize(G);
  }
  // Stopped while building (every rank learns it; mpirun signals them all): there is no
  // state to keep yet, so the run ends here, its folder as it was.
  if (ranks::max({InterruptGuard::interrupted() ? 1.0 : 0.0})[0] > 0) {
    ranks::mark_agreed();
    throw Interrupted(fmt::format("while the MD boxes were being built ({:.0f} s in): nothing was written and "
                                  "there is nothing to resume; start the run again",
                                  seconds_since(t0)));
  }
  stress_.assign(G, md::Mat3{});
  for (std::size_t g = 0; g < G; ++g)
    if (boxes_[g]) stress_[g] = boxes_[g]->stress_gpa();
  shape_.assign(G, {});
  temperature_.assign(G, 0.0);
  energy_.assign(G, 0.0);
  owed_.assign(G, 0.0);
  group_seconds_.assign(G, 0.0);
  rotation_.assign(n, as_array(Mat3d::Identity()));
  audits_.clear();
  audit_owed_.clear();
  if (!failed) start_audits(groups_.draw_auditors(0));
  md_seconds_ += seconds_since(t0);
  publish(p, failed, false, 0.0, {}, {}, {});
  atom_steps_ = static_cast<std::int64_t>(G) * atoms_per_point() * cfg_.relax_steps;
  atom_steps_unshared_ = static_cast<std::int64_t>(n) * atoms_per_point() * cfg_.relax_steps;
}

// New auditors' private boxes start as copies of their groups' boxes.
template <int Dim>
void MdClosure<Dim>::start_audits(const std::vector<std::size_t>& points) {
  for (std::size_t q : points) {
    const std::size_t g = groups_.group_of(q);
    if (!mine(g)) continue;
    audits_.insert_or_assign(q, *boxes_[g]);
    audit_stress_[q] = stress_[g];
    audit_owed_[q] = owed_[g];
  }
}

template <int Dim>
void MdClosure<Dim>::apply_split(const BoxGroups::Split& split) {
  for (std::size_t q : split.dropped) audits_.erase(q), audit_stress_.erase(q), audit_owed_.erase(q);
  const std::size_t G = groups_.groups();
  boxes_.resize(G);
  owner_.resize(G, 0);
  stress_.resize(G);
  shape_.resize(G);
  temperature_.resize(G);
  energy_.resize(G);
  owed_.resize(G, 0.0);
  group_seconds_.resize(G, 0.0);
  for (const auto& c : split.clones) {  // a new group runs where its parent did, from a copy
    owner_[c.to] = owner_[c.from];
    stress_[c.to] = stress_[c.from];
    shape_[c.to] = shape_[c.from];
    temperature_[c.to] = temperature_[c.from];
    energy_[c.to] = energy_[c.from];
    owed_[c.to] = owed_[c.from];  // a copy of the box, so of what it owes
    if (mine(c.from)) boxes_[c.to] = std::make_unique<md::System>(*boxes_[c.from]);
  }
}

template <int Dim>
typename MdClosure<Dim>::Power MdClosure<Dim>::power_of(const Points<Dim>& p, std::size_t q) const {
  // The continuum's rate of deformation seen in the box's frame, R^T D R (the box's
  // stress is turned by R before the continuum uses it), and the power of the viscous
  // stresses the step's forces used: the tensor viscosity's, less the linear viscosity's q
  // on each normal stress (GPa/ps). The viscosity's work is the shock's entropy (von
  // Neumann-Richtmyer): left out, a shocked box gets none of it.
  const Mat3d R = as_matrix(rotation_[q]);
  Mat3d L = Mat3d::Zero(), viscous = Mat3d::Zero();
  for (int a = 0; a < Dim; ++a)
    for (int b = 0; b < Dim; ++b) {
      if (p.viscous[a * Dim + b]) viscous(a, b) += p.viscous[a * Dim + b][q] * cfg_.units.stress_GPa;
      if (a == b && p.viscous_pressure) viscous(a, b) -= p.viscous_pressure[q] * cfg_.units.stress_GPa;
      L(a, b) = p.L(q, a, b) / cfg_.units.time_ps;
    }
  const Mat3d D = 0.5 * (L + L.transpose());
  return {as_array(R.transpose() * D * R), (viscous.array() * D.array()).sum()};
}

template <int Dim>
std::pair<double, double> MdClosure<Dim>::advance(md::System& box, const md::Mat3& L, const Power& power, int steps,
                                                  md::Mat3& stress, double& owed) {
  if (!consistent()) {
    multiscale::advance_box(box, L, steps, cfg_.dt, cfg_.sample, stress);
    box.compact();
    return {0.0, 0.0};
  }
  // Eq. 7.11: the continuum's work on the box over the step against its own energy change.
  constexpr double GPa_A3_in_eV = 1.0 / 160.21766208;  // 1 GPa x 1 A^3 in eV
  auto stress_power = [&] {
    double w = 0.0;
    for (int c = 0; c < 9; ++c) w += stress[c] * power.rate[c];
    return w;
  };
  const double dt_ps = steps * cfg_.dt;
  const double e0 = box.potential_energy() + box.thermal_kinetic_energy(), v0 = box.box().volume();
  const double before = stress_power();  // the stress of the last sample, sigma^n
  multiscale::advance_box(box, L, steps, cfg_.dt, cfg_.sample, stress);
  // The box's stress over the step, time-centred: the mean of its samples at the step's
  // ends, or the step's own average where that is sampled. The forces' lagged sigma^n
  // alone under-counts a compression by (sigma^{n+1} - sigma^n) : D dt / 2 a step, an error
  // of the order of the step that left the 1-D bar at 2.5 km/s with 86% of the jump
  // conditions' energy at dt = 0.01 ps and 95% at 0.002 (docs/theory.md).
  const double box_power = cfg_.sample == multiscale::StressSample::average ? stress_power()
                                                                             : 0.5 * (before + stress_power());
  const double work = 0.5 * (v0 + box.box().volume()) * (box_power + power.viscous) * dt_ps * GPa_A3_in_eV;
  // What the box is owed this step, and what it still owes from earlier ones. The work
  // and the box's own change differ by the viscous heat and by the sampled stress's noise;
  // a removal is at most half the thermal energy a cold box has, and the rest is carried
  // into the next steps, never dropped: dropping it would keep every positive swing and
  // lose the negative ones, a ratchet that heats the box more the shorter the step
  // (3,495 K at dt 0.01 ps, 11,758 K at 0.002 in the 1-D bar at 2.5 km/s).
  double add = work - (box.potential_energy() + box.thermal_kinetic_energy() - e0) + owed;
  // At most half the thermal energy a step: taking it all would leave a box at 0 K.
  const double room = 0.5 * box.thermal_kinetic_energy();
  owed = 0.0;
  if (add < -room) owed = add + room, add = -room;
  box.add_energy(add);
  box.compact();
  return {add, -owed};
}

template <int Dim>
void MdClosure<Dim>::update_stress(const Points<Dim>& p, double dt) {
  const std::size_t n = p.size();
  const int steps = cfg_.md_steps(dt);
  if (steps == 0)
    throw InputError(fmt::format("md_closure: the continuum step ({} ps) is not a whole number of MD "
                                 "steps of {} ps",
                                 dt * cfg_.units.time_ps, cfg_.dt));
  const double dt_ps = dt * cfg_.units.time_ps;
  std::vector<md::Mat3> L(n, md::Mat3{});
  for (std::size_t q = 0; q < n; ++q)
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) L[q][3 * a + b] = p.L(q, a, b) / cfg_.units.time_ps;  // 1/ps
  // Who leaves, before any box steps; then each group's gradient, its members' mean.
  apply_split(groups_.split(L, dt_ps));
  ++macro_step_;
  start_audits(groups_.draw_auditors(macro_step_));
  groups_.keep_means(L);
  const std::size_t G = groups_.groups();
  // Eq. 7.11's power: each group's the mean over its members; each auditor's its own.
  std::vector<std::size_t> todo;
  for (std::size_t g = 0; g < G; ++g)
    if (mine(g)) todo.push_back(g);
  std::vector<Power> power(G);
  std::map<std::size_t, Power> audit_power;
  if (consistent()) {
    for (std::size_t g : todo) {
      Power sum;
      for (std::size_t q : groups_.members(g)) {
        const Power one = power_of(p, q);
        for (int c = 0; c < 9; ++c) sum.rate[c] += one.rate[c];
        sum.viscous += one.viscous;
      }
      const double m = static_cast<double>(groups_.members(g).size());
      for (int c = 0; c < 9; ++c) power[g].rate[c] = sum.rate[c] / m;
      power[g].viscous = sum.viscous / m;
    }
  }
  std::vector<std::pair<std::size_t, md::System*>> audited;
  std::vector<md::Mat3> audit_stress;  // each auditor's last sample, then its new one
  for (auto& [q, box] : audits_) {
    audited.emplace_back(q, &box);
    audit_stress.push_back(audit_stress_.at(q));
    if (consistent()) audit_power[q] = power_of(p, q);
  }
  std::vector<double> injected(G, 0.0), short_of(G, 0.0);
  std::optional<ranks::Failure> failed;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    // The groups' boxes, then the auditors' (failures name the lowest point).
    std::vector<double> seconds(todo.size(), 0.0);
    batch_.each_box(todo.size(), 0, &seconds, [&](std::size_t k) {
      const std::size_t g = todo[k];
      try {
        std::tie(injected[g], short_of[g]) =
            advance(*boxes_[g], groups_.kept(g), power[g], steps, stress_[g], owed_[g]);
      } catch (const std::exception& e) {
        throw RunError(fmt::format("(point {}) {}", groups_.members(g).front(), e.what()));
      }
    });
    for (std::size_t k = 0; k < todo.size(); ++k) group_seconds_[todo[k]] += seconds[k];
    batch_.each_box(audited.size(), 0, nullptr, [&](std::size_t k) {
      const std::size_t q = audited[k].first;
      advance(*audited[k].second, L[q], consistent() ? audit_power[q] : Power{}, steps, audit_stress[k],
              audit_owed_.at(q));
    });
  } catch (const std::exception& e) {
    failed = ranks::Failure{ranks::Failure::run, where() + e.what()};
  }
  md_seconds_ += seconds_since(t0);
  // The audit: each auditor's private stress against its group's (box frame).
  std::vector<std::array<double, 4>> audit(audited.size());
  for (std::size_t k = 0; k < audited.size(); ++k) {
    const std::size_t q = audited[k].first;
    const md::Mat3& own = audit_stress[k];
    const md::Mat3& shared = stress_[groups_.group_of(q)];
    audit[k] = {static_cast<double>(q), 0.0, 0.0, 0.0};
    for (int c = 0; c < 9; ++c) {
      const double d = own[c] - shared[c];
      audit[k][1] += d * d, audit[k][2] += own[c] * own[c];
      audit[k][3] = std::max(audit[k][3], std::abs(d));
    }
    audit_stress_[q] = own;
  }
  groups_.accumulate(L, dt_ps);
  turn(p, dt_ps);
  if (nan_point_ && *nan_point_ < n && mine(groups_.group_of(*nan_point_)))
    stress_[groups_.group_of(*nan_point_)][0] = std::nan("");
  std::int64_t auditors = 0;
  for (std::size_t q = 0; q < n; ++q) auditors += groups_.auditor(q);
  publish(p, failed, true, dt, injected, short_of, audit);
  atom_steps_ += (static_cast<std::int64_t>(G) + auditors) * atoms_per_point() * steps;
  atom_steps_unshared_ += static_cast<std::int64_t>(n) * atoms_per_point() * steps;
  if (cfg_.share.by_state) apply_merge(groups_.merge(box_states()));
}

template <int Dim>
std::vector<BoxState> MdClosure<Dim>::box_states() const {
  const double l0 = cfg_.cells * box_lattice_constant(), m = pot_.mass(0);
  std::vector<BoxState> s(groups_.groups());
  for (std::size_t g = 0; g < s.size(); ++g) {
    for (int k = 0; k < 6; ++k) s[g].shape[k] = shape_[g][k] / l0;
    s[g].energy = energy_[g] * m;
    s[g].stress = stress_[g];
  }
  return s;
}

template <int Dim>
void MdClosure<Dim>::apply_merge(const BoxGroups::Merge& merge) {
  if (merge.absorbed.empty()) return;
  for (std::size_t q : merge.dropped) audits_.erase(q), audit_stress_.erase(q), audit_owed_.erase(q);
  // Each survivor's box is owed what makes its energy (with what it owes) its members'
  // mean over the merged boxes: the energy the continuum put into the absorbed ones is kept.
  const double mass = atoms_per_point() * pot_.mass(0);  // amu
  auto held = [&](std::size_t g) { return energy_[g] * mass + owed_[g]; };
  std::map<std::size_t, std::pair<double, double>> mean;  // survivor -> (sum n E, sum n)
  std::vector<std::uint8_t> absorbed(merge.index.size(), 0);
  for (const auto& [h, g] : merge.absorbed) {
    absorbed[h] = 1;
    const double ng = static_cast<double>(merge.size_before[g]), nh = static_cast<double>(merge.size_before[h]);
    auto& sum = mean.try_emplace(g, ng * held(g), ng).first->second;
    sum.first += nh * held(h), sum.second += nh;
    for (int c = 0; c < 9; ++c) {
      const double d = stress_[h][c] - stress_[g][c];
      merge_d2_ += d * d, merge_s2_ += stress_[g][c] * stress_[g][c];
      merge_max_gpa_ = std::max(merge_max_gpa_, std::abs(d));
    }
    ++merges_;
    merged_points_ += static_cast<std::int64_t>(merge.size_before[h]);
    group_seconds_[g] += group_seconds_[h];
  }
  if (consistent())
    for (const auto& [g, sum] : mean) owed_[g] += sum.first / sum.second - held(g);
  // Every per-group array keeps its survivors at their new indices (an absorbed box ends).
  auto compact = [&](auto& v) {
    std::remove_reference_t<decltype(v)> kept(groups_.groups());
    for (std::size_t g = 0; g < merge.index.size(); ++g)
      if (!absorbed[g]) kept[merge.index[g]] = std::move(v[g]);
    v = std::move(kept);
  };
  compact(boxes_);
  compact(owner_);
  compact(stress_);
  compact(shape_);
  compact(temperature_);
  compact(energy_);
  compact(owed_);
  compact(group_seconds_);
}

// R <- C(W dt) R C(W' dt)^T: the crystal turns with the point's spin W, the box's with
// the spin W' its upper-triangular gradient keeps. Every point, on every rank.
template <int Dim>
void MdClosure<Dim>::turn(const Points<Dim>& p, double dt_ps) {
  if constexpr (Dim > 1) {
    for (std::size_t q = 0; q < p.size(); ++q) {
      md::Mat3 g{};
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) g[3 * a + b] = p.L(q, a, b) / cfg_.units.time_ps;
      const md::Mat3& box = groups_.kept(groups_.group_of(q));  // the gradient its box followed
      if (box == g && md::is_upper_triangular(g)) continue;    // W' = W: R unchanged
      const Mat3d G = as_matrix(g), Gu = as_matrix(md::upper_triangular(box));
      const Mat3d W = 0.5 * (G - G.transpose()), Wb = 0.5 * (Gu - Gu.transpose());
      rotation_[q] = as_array(cayley(W, dt_ps) * as_matrix(rotation_[q]) * cayley(Wb, dt_ps).transpose());
    }
  }
}

// The point's stress: its group's box's, turned by the point's rotation (identity in 1-D).
template <int Dim>
void MdClosure<Dim>::set_point_stress(const Points<Dim>& p, std::size_t q) const {
  const md::Mat3& box = stress_[groups_.group_of(q)];
  if constexpr (Dim == 1) {
    p.stress[0][q] = box[0] / cfg_.units.stress_GPa;
  } else {
    const Mat3d R = as_matrix(rotation_[q]);
    const Mat3d s = R * as_matrix(box) * R.transpose();
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.sigma(q, a, b) = s(a, b) / cfg_.units.stress_GPa;
    p.set_sigma_zz(q, s(2, 2) / cfg_.units.stress_GPa);  // 2-D: the box's own, R turns in-plane only
  }
}

template <int Dim>
void MdClosure<Dim>::publish(const Points<Dim>& p, std::optional<ranks::Failure> failed, bool strain, double dt,
                             const std::vector<double>& injected, const std::vector<double>& short_of,
                             const std::vector<std::array<double, 4>>& audit) {
  const std::size_t G = groups_.groups();
  // This rank's records in group order, then its auditors'; every rank knows how many
  // every other sends (the groups and their owners are replicated).
  std::vector<double> out;
  for (std::size_t g = 0; g < G && !failed; ++g) {
    if (!mine(g)) continue;
    for (int c = 0; c < 9; ++c) out.push_back(stress_[g][c]);
    const md::Box& b = boxes_[g]->box();
    for (const double v : {b.lx, b.ly, b.lz, b.xy, b.xz, b.yz}) out.push_back(v);
    out.push_back(static_cast<double>(boxes_[g]->neighbor_builds()));
    out.push_back(injected.empty() ? 0.0 : injected[g]);
    out.push_back(short_of.empty() ? 0.0 : short_of[g]);
    out.push_back(boxes_[g]->temperature());
    out.push_back(owed_[g]);
    out.push_back(specific_energy(*boxes_[g]));
    for (int c = 0; c < 9; ++c)
      if (!std::isfinite(stress_[g][c]))
        failed = ranks::Failure{ranks::Failure::run,
                                fmt::format("{}the MD box of material point {} gave a non-finite stress ({} GPa)",
                                            where(), groups_.members(g).front(), stress_[g][c])};
  }
  for (const auto& a : audit) out.insert(out.end(), a.begin(), a.end());
  std::vector<int> counts(static_cast<std::size_t>(ranks::size()), 0);
  for (std::size_t g = 0; g < G; ++g) counts[owner_[g]] += kGroupRecord;
  // Auditors report from a macro step only (`strain`): the relaxation has none to send.
  for (std::size_t q = 0; q < groups_.points() && strain; ++q)
    if (groups_.auditor(q)) counts[owner_[groups_.group_of(q)]] += 4;
  if (!failed && out.size() != static_cast<std::size_t>(counts[ranks::rank()]))
    throw std::logic_error(fmt::format("md_closure: {} values to publish where the groups expect {}", out.size(),
                                       counts[ranks::rank()]));
  if (failed) out.assign(static_cast<std::size_t>(counts[ranks::rank()]), std::nan(""));
  const std::vector<double> all = ranks::all_gather(out, counts);
  if (const auto f = ranks::first_failure(failed)) {
    ranks::mark_agreed();
    ranks::raise(*f);
  }
  // Read back in rank order: each rank's groups by id, then its auditors.
  std::vector<std::array<double, 4>> audits;
  std::size_t at = 0;
  for (int r = 0; r < ranks::size(); ++r) {
    for (std::size_t g = 0; g < G; ++g) {
      if (owner_[g] != r) continue;
      const double* rec = &all[at];
      at += kGroupRecord;
      for (int c = 0; c < 9; ++c) stress_[g][c] = rec[c];
      for (int c = 0; c < 7; ++c) shape_[g][c] = rec[9 + c];
      injected_ev_ += rec[16];
      temperature_[g] = rec[18];
      owed_[g] = rec[19];
      energy_[g] = rec[20];
    }
    for (std::size_t q = 0; q < groups_.points() && strain; ++q) {
      if (!groups_.auditor(q) || owner_[groups_.group_of(q)] != r) continue;
      audits.push_back({all[at], all[at + 1], all[at + 2], all[at + 3]});
      at += 4;
    }
  }
  // The audit's sums in point order: the same on any rank count.
  std::sort(audits.begin(), audits.end());
  for (const auto& a : audits) {
    audit_d2_ += a[1], audit_s2_ += a[2];
    audit_max_gpa_ = std::max(audit_max_gpa_, a[3]);
    ++audit_samples_;
  }
  neighbor_builds_ = 0;
  for (std::size_t g = 0; g < G; ++g) neighbor_builds_ += static_cast<std::int64_t>(shape_[g][6]);
  const double l0 = cfg_.cells * props_.equilibrium.lattice_constant;
  for (std::size_t q = 0; q < p.size(); ++q) {
    set_point_stress(p, q);
    if (!strain) continue;
    if constexpr (Dim == 1) {
      p.strain[0][q] = shape_[groups_.group_of(q)][0] / l0 - 1.0;  // the box's engineering strain
    } else {
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.eps(q, a, b) += 0.5 * dt * (p.L(q, a, b) + p.L(q, b, a));
    }
  }
}

template <int Dim>
std::vector<material::PointField> MdClosure<Dim>::point_fields(const Points<Dim>&) const {
  const std::size_t n = groups_.points();
  material::PointField T{"temperature", std::vector<double>(n)};
  for (std::size_t q = 0; q < n; ++q) T.values[q] = temperature_[groups_.group_of(q)];
  // The box's energy per unit mass above the 0 K crystal at rest (continuum units, as
  // mie_gruneisen's): what the jump conditions' (V0 - V) sigma / 2 is compared with.
  const double to_continuum = 1.0 / (units::mvv2e * std::pow(cfg_.units.velocity_A_per_ps(), 2));
  const double cold = props_.equilibrium.energy_per_atom / pot_.mass(0);
  material::PointField e{"internal_energy", std::vector<double>(n)};
  for (std::size_t q = 0; q < n; ++q) e.values[q] = (energy_[groups_.group_of(q)] - cold) * to_continuum;
  std::vector<material::PointField> f{std::move(T), std::move(e)};
  if constexpr (Dim == 1) {
    // The box's lateral stresses, which the 1-D points keep no array for (continuum units).
    material::PointField yy{"stress_yy", std::vector<double>(n)}, zz{"stress_zz", std::vector<double>(n)};
    for (std::size_t q = 0; q < n; ++q) {
      const md::Mat3& box = stress_[groups_.group_of(q)];
      yy.values[q] = box[4] / cfg_.units.stress_GPa, zz.values[q] = box[8] / cfg_.units.stress_GPa;
    }
    f.push_back(std::move(yy));
    f.push_back(std::move(zz));
  }
  return f;
}

template <int Dim>
std::string MdClosure<Dim>::point_model_dump(std::size_t q, std::int64_t step,
                                             const std::vector<std::string>& fields) const {
  // The rank that runs q's box writes it; rank 0 gathers (the others send nothing).
  std::ostringstream text;
  if (q < groups_.points() && mine(groups_.group_of(q))) {
    const md::System& box = *boxes_[groups_.group_of(q)];
    if (fields.empty()) {
      md::write_lammps_dump(text, step, box.snapshot(), box.box());
    } else {  // per-atom sums of the same state on a copy that keeps them
      md::SystemOptions o = box_options();
      o.per_atom = md::dump_needs_per_atom(fields);
      md::System copy(box.snapshot(), box.box(), box.potential(), o);
      copy.refresh();
      md::write_dump_frame(text, copy, fields, 1, step);
    }
  }
  return ranks::size() > 1 ? ranks::gather_to_root(text.str()) : text.str();
}

template <int Dim>
double MdClosure<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  return std::sqrt(modulus() / p.density(q));
}

template <int Dim>
double MdClosure<Dim>::signal_speed(const Points<Dim>& p, std::size_t q) const {
  const double rho = p.density(q);
  const double m = cfg_.stiffness->modulus_at(props_.density / rho) / cfg_.units.stress_GPa;
  return std::sqrt(std::max(m, modulus()) / rho);
}

namespace {

// Boxes keyed by an index (a group, or an auditor's point), each written with its
// length so that rank 0 can put every rank's in order.
// A box, with the last stress an auditor's power needs after it.
// An auditor's box also carries its last stress and what it owes (eq. 7.11).
void save_box(std::ostream& out, const md::System& box, const md::Mat3* stress = nullptr, double owed = 0.0) {
  box.save(out);
  if (stress) {
    out.write(reinterpret_cast<const char*>(stress->data()), sizeof(double) * 9);
    write_raw(out, owed);
  }
}
std::string box_bytes(const md::System& box, const md::Mat3* stress = nullptr, double owed = 0.0) {
  std::ostringstream b(std::ios::binary);
  save_box(b, box, stress, owed);
  return b.str();
}
void pack(std::ostream& out, std::uint64_t key, const std::string& bytes) {
  write_raw(out, key);
  write_raw(out, static_cast<std::uint64_t>(bytes.size()));
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}
std::map<std::uint64_t, std::string> unpack(const std::string& all) {
  std::map<std::uint64_t, std::string> r;
  std::istringstream in(all, std::ios::binary);
  std::uint64_t key = 0, len = 0;
  while (in.peek() != std::char_traits<char>::eof()) {
    read_raw(in, key);
    read_raw(in, len);
    std::string bytes(len, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(len));
    r[key] = std::move(bytes);
  }
  return r;
}

}  // namespace

template <int Dim>
void MdClosure<Dim>::save(std::ostream& out) const {
  // One process writes its boxes straight to `out` (hundreds of MB on the jet: no copy
  // of them in memory); under MPI rank 0 gathers every rank's first, keyed for their order.
  const bool gather = ranks::size() > 1;
  std::map<std::uint64_t, std::string> groups, audits;
  if (gather) {
    std::ostringstream group_boxes(std::ios::binary), audit_boxes(std::ios::binary);
    for (std::size_t g = 0; g < boxes_.size(); ++g)
      if (boxes_[g]) pack(group_boxes, g, box_bytes(*boxes_[g]));
    for (const auto& [q, box] : audits_)
      pack(audit_boxes, q, box_bytes(box, &audit_stress_.at(q), audit_owed_.at(q)));
    groups = unpack(ranks::gather_to_root(group_boxes.str()));
    audits = unpack(ranks::gather_to_root(audit_boxes.str()));
    if (!ranks::root()) return;
  }
  const std::uint64_t n = groups_.points();
  write_raw(out, n);
  write_raw(out, atom_steps_);
  write_raw(out, atom_steps_unshared_);
  write_raw(out, macro_step_);
  groups_.save(out);
  for (const auto& [g, bytes] : groups) out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!gather)
    for (const auto& box : boxes_)
      if (box) save_box(out, *box);
  write_raw(out, static_cast<std::uint64_t>(gather ? audits.size() : audits_.size()));
  for (const auto& [q, bytes] : audits) {  // each box, then its last stress
    write_raw(out, q);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  }
  if (!gather)
    for (const auto& [q, box] : audits_) {
      write_raw(out, static_cast<std::uint64_t>(q));
      save_box(out, box, &audit_stress_.at(q), audit_owed_.at(q));
    }
  // Eq. 7.11's and the audit's tallies, every point's rotation and every group's box
  // shape and last stress (the next step's sigma^n): the same on every rank.
  for (const double v : {injected_ev_, audit_d2_, audit_s2_, audit_max_gpa_}) write_raw(out, v);
  write_raw(out, audit_samples_);
  for (const double v : {merge_d2_, merge_s2_, merge_max_gpa_}) write_raw(out, v);
  write_raw(out, merges_);
  write_raw(out, merged_points_);
  for (const auto& r : rotation_) out.write(reinterpret_cast<const char*>(r.data()), sizeof(double) * 9);
  for (const auto& s : stress_) out.write(reinterpret_cast<const char*>(s.data()), sizeof(double) * 9);
  for (const auto& s : shape_) out.write(reinterpret_cast<const char*>(s.data()), sizeof(double) * 7);
  for (const double v : owed_) write_raw(out, v);
  // prepare = npt: the prepared lattice (decks that place the lattice write nothing more).
  if (cfg_.prepare == BoxPrepare::npt) {
    const PreparedLattice l = prepared_.value_or(PreparedLattice{});
    for (const double v : {l.lattice_constant, l.pressure_gpa, l.temperature}) write_raw(out, v);
  }
}

template <int Dim>
void MdClosure<Dim>::load(std::istream& in) {
  // Each box takes far more than 64 bytes: the bound only keeps a damaged count from an
  // allocation; the point count is checked against the deck's points by the caller.
  const std::uint64_t n = read_count(in, 64, "md_closure points");
  read_raw(in, atom_steps_);
  read_raw(in, atom_steps_unshared_);
  read_raw(in, macro_step_);
  if (!in) throw InputError("checkpoint: the MD boxes are truncated");
  groups_.load(in, cfg_.share);  // a resumed run has not built its groups: their options are the deck's
  if (groups_.points() != n)
    throw InputError(fmt::format("checkpoint: the groups hold {} points, the boxes {}", groups_.points(), n));
  const std::size_t G = groups_.groups();
  spread_groups(std::vector<double>(G, 1.0));
  boxes_.clear();
  boxes_.resize(G);
  temperature_.assign(G, 0.0);
  energy_.assign(G, 0.0);
  // Every box is read (the run's own figures follow them); this rank keeps its own.
  for (std::size_t g = 0; g < G; ++g) {
    try {
      md::System box = md::System::load(in, pot_, box_options());
      box.compact();  // as the run keeps it between macro steps
      temperature_[g] = box.temperature();
      energy_[g] = specific_energy(box);
      if (mine(g)) boxes_[g] = std::make_unique<md::System>(std::move(box));
    } catch (const RunError& e) {  // a box the file describes that no run makes
      throw InputError(fmt::format("the MD box of group {} (point {}): {}", g, groups_.members(g).front(), e.what()));
    }
  }
  const std::uint64_t auditors = read_count(in, 64, "md_closure auditors");
  audits_.clear();
  audit_stress_.clear();
  audit_owed_.clear();
  for (std::uint64_t k = 0; k < auditors; ++k) {
    std::uint64_t q = 0;
    read_raw(in, q);
    if (!in || q >= n || !groups_.auditor(q)) throw InputError(fmt::format("checkpoint: an auditor {} out of place", q));
    md::System box = md::System::load(in, pot_, box_options());
    box.compact();
    md::Mat3 s{};
    double owed = 0.0;
    in.read(reinterpret_cast<char*>(s.data()), sizeof(double) * 9);
    read_raw(in, owed);
    if (mine(groups_.group_of(q)))
      audits_.insert_or_assign(q, std::move(box)), audit_stress_[q] = s, audit_owed_[q] = owed;
  }
  for (double* v : {&injected_ev_, &audit_d2_, &audit_s2_, &audit_max_gpa_}) read_raw(in, *v);
  read_raw(in, audit_samples_);
  for (double* v : {&merge_d2_, &merge_s2_, &merge_max_gpa_}) read_raw(in, *v);
  read_raw(in, merges_);
  read_raw(in, merged_points_);
  rotation_.assign(n, md::Mat3{});
  stress_.assign(G, md::Mat3{});
  shape_.assign(G, {});
  for (auto& r : rotation_) in.read(reinterpret_cast<char*>(r.data()), sizeof(double) * 9);
  for (auto& s : stress_) in.read(reinterpret_cast<char*>(s.data()), sizeof(double) * 9);
  for (auto& s : shape_) in.read(reinterpret_cast<char*>(s.data()), sizeof(double) * 7);
  owed_.assign(G, 0.0);
  for (double& v : owed_) read_raw(in, v);
  prepared_.reset();
  if (cfg_.prepare == BoxPrepare::npt) {
    PreparedLattice l;
    for (double* v : {&l.lattice_constant, &l.pressure_gpa, &l.temperature}) read_raw(in, *v);
    prepared_ = l;
  }
  if (!in) throw InputError("checkpoint: the MD boxes' rotations and stresses are truncated");
  neighbor_builds_ = 0;
  for (const auto& s : shape_) {
    // The build count is a whole number a run wrote; a damaged one must not reach the cast.
    if (!(s[6] >= 0.0 && s[6] <= 9.0e15) || s[6] != std::floor(s[6]))
      throw InputError(fmt::format("checkpoint: an MD box's neighbour-build count {} is not a count", s[6]));
    neighbor_builds_ += static_cast<std::int64_t>(s[6]);
  }
  group_seconds_.assign(G, 0.0);
  if (const char* v = std::getenv("MPMX_TEST_NAN_POINT")) nan_point_ = std::strtoull(v, nullptr, 10);
}

template <int Dim>
bool MdClosure<Dim>::rebalance(double threshold) {
  if (ranks::size() == 1) return false;
  const std::size_t G = groups_.groups();
  std::vector<double> mine_cost;
  double total = 0.0;
  std::vector<int> counts(static_cast<std::size_t>(ranks::size()), 0);
  for (std::size_t g = 0; g < G; ++g) {
    ++counts[owner_[g]];
    if (mine(g)) mine_cost.push_back(group_seconds_[g]), total += group_seconds_[g];
  }
  const double slowest = ranks::max({total})[0], mean = ranks::sum(total) / ranks::size();
  const std::vector<double> gathered = ranks::all_gather(mine_cost, counts);
  std::vector<double> cost(G, 0.0);
  std::size_t at = 0;
  for (int r = 0; r < ranks::size(); ++r)
    for (std::size_t g = 0; g < G; ++g)
      if (owner_[g] == r) cost[g] = gathered[at++];
  group_seconds_.assign(G, 0.0);  // the next check measures afresh
  if (!(mean > 0.0) || slowest <= threshold * mean) return false;
  const std::vector<int> before = owner_;
  spread_groups(cost);
  if (owner_ == before) return false;
  // Each box (and its auditors') goes to its group's new rank as a checkpoint writes it:
  // the run goes on bit for bit.
  std::vector<std::ostringstream> out(static_cast<std::size_t>(ranks::size()));
  for (std::size_t g = 0; g < G; ++g) {
    if (before[g] != ranks::rank() || owner_[g] == ranks::rank()) continue;
    auto& o = out[static_cast<std::size_t>(owner_[g])];
    pack(o, 2 * g, box_bytes(*boxes_[g]));
    boxes_[g].reset();
  }
  for (auto it = audits_.begin(); it != audits_.end();) {
    const std::size_t g = groups_.group_of(it->first);
    if (owner_[g] == ranks::rank()) {
      ++it;
      continue;
    }
    auto& o = out[static_cast<std::size_t>(owner_[g])];
    pack(o, 2 * it->first + 1, box_bytes(it->second, &audit_stress_.at(it->first), audit_owed_.at(it->first)));
    audit_stress_.erase(it->first);
    audit_owed_.erase(it->first);
    it = audits_.erase(it);
  }
  std::vector<std::string> bytes;
  for (auto& o : out) bytes.push_back(o.str());
  for (const auto& [key, box] : unpack(ranks::exchange(bytes))) {
    std::istringstream b(box, std::ios::binary);
    md::System s = md::System::load(b, pot_, box_options());
    s.compact();
    if (key % 2 == 0) {
      boxes_[key / 2] = std::make_unique<md::System>(std::move(s));
    } else {
      const std::size_t q = key / 2;
      audits_.insert_or_assign(q, std::move(s));
      md::Mat3 last{};
      double owed = 0.0;
      b.read(reinterpret_cast<char*>(last.data()), sizeof(double) * 9);
      read_raw(b, owed);
      audit_stress_[q] = last;
      audit_owed_[q] = owed;
    }
  }
  return true;
}

template <int Dim>
std::vector<material::Figure> MdClosure<Dim>::figures() const {
  const auto& eq = props_.equilibrium;
  std::vector<material::Figure> f{{"md.atoms_per_point", std::int64_t{atoms_per_point()}},
                                  {"md.points", static_cast<std::int64_t>(groups_.points())},
                                  {"md.lattice_constant_A", box_lattice_constant()},
                                  {"md.energy_per_atom_eV", eq.energy_per_atom},
                                  {"md.c11_GPa", eq.c11_gpa},
                                  {"md.density", density()},
                                  {"md.energy_injected_eV", injected_ev_},  // eq. 7.11, running total
                                  {"md.energy_shortfall_eV", energy_shortfall_ev()},  // owed at the end
                                  {"md.neighbor_builds", neighbor_builds_},
                                  {"md.atom_steps", atom_steps_},
                                  {"md.atom_steps_unshared", atom_steps_unshared_},
                                  {"md.boxes.initial", static_cast<std::int64_t>(groups_.groups_initial())},
                                  {"md.boxes.max", static_cast<std::int64_t>(groups_.groups_max())},
                                  {"md.boxes.final", static_cast<std::int64_t>(groups_.groups())}};
  if (prepared_) {  // prepare = npt: the constant above is NPT's; the 0 K one and the NPT run's means
    f.emplace_back("md.lattice_constant_0K_A", eq.lattice_constant);
    f.emplace_back("md.prepare.pressure_GPa", prepared_->pressure_gpa);
    f.emplace_back("md.prepare.temperature_K", prepared_->temperature);
    f.emplace_back("md.prepare.steps", std::int64_t{cfg_.prepare_steps});
  }
  if (audit_samples_ > 0) {
    f.emplace_back("md.share.audit_rel_rms", audit_rel_rms());
    f.emplace_back("md.share.audit_max_gpa", audit_max_gpa());
  }
  if (cfg_.share.by_state) {
    f.emplace_back("md.share.merges", merges_);
    f.emplace_back("md.share.merged_points", merged_points_);
    if (merges_ > 0) {
      f.emplace_back("md.share.merge_rel_rms", merge_s2_ > 0.0 ? std::sqrt(merge_d2_ / merge_s2_) : 0.0);
      f.emplace_back("md.share.merge_max_gpa", merge_max_gpa_);
    }
  }
  return f;
}

template class MdClosure<1>;
template class MdClosure<2>;
template class MdClosure<3>;

}  // namespace mpmx::multiscale
