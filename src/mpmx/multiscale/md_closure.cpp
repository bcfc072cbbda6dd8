#include "mpmx/multiscale/md_closure.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/core/binary.hpp"
#include "mpmx/md/lattice.hpp"

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

// The record a point's box returns to every rank: its stress (GPa), its box and its
// neighbour-list builds.
constexpr int kRecord = 16;

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

}  // namespace

MdClosureProperties md_closure_properties(const md::PotentialSpec& spec, const units::UnitSystem& u) {
  return properties(md::fcc_equilibrium(md::Potential(spec)), u);
}

int MdClosureConfig::md_steps(double dt_continuum) const {
  const double steps = dt_continuum * units.time_ps / dt;
  const long k = std::lround(steps);
  return k >= 1 && std::abs(steps - k) <= 1e-6 * steps ? static_cast<int>(k) : 0;
}

template <int Dim>
MdClosure<Dim>::MdClosure(const MdClosureConfig& config)
    : cfg_(config), pot_(config.potential), props_(properties(md::fcc_equilibrium(pot_), config.units)),
      batch_(config.threads) {}

template <int Dim>
md::SystemOptions MdClosure<Dim>::box_options() const {
  md::SystemOptions o;
  o.skin = cfg_.skin;
  o.mixed_precision = cfg_.mixed_precision;
  return o;
}

template <int Dim>
void MdClosure<Dim>::initialize(const Points<Dim>& p) {
  spread_ = multiscale::Spread(p.size());
  const std::size_t first = spread_.begin(), m = spread_.count();
  if (const char* v = std::getenv("MPMX_TEST_NAN_POINT")) nan_point_ = std::strtoull(v, nullptr, 10);
  const double a0 = props_.equilibrium.lattice_constant;
  const auto t0 = std::chrono::steady_clock::now();
  // Each point's box built on the threads (section 6.2), then kept in point order.
  std::vector<std::optional<md::System>> built(m);
  std::optional<ranks::Failure> failed;
  try {
    batch_.for_each(m, [&](std::size_t k) {
      const std::size_t q = first + k;
      try {
        md::System box(md::fcc(cfg_.cells, cfg_.cells, cfg_.cells, a0, p.strain[0][q]), pot_, box_options());
        if (cfg_.temperature > 0) box.thermalize(cfg_.temperature, cfg_.seed, q);
        box.advance(static_cast<int>(cfg_.relax_steps), cfg_.dt);  // zero strain rate
        built[k].emplace(std::move(box));
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
  boxes_.clear();
  boxes_.reserve(m);
  stress_.assign(m, md::Mat3{});
  if (!failed)
    for (std::size_t k = 0; k < m; ++k) {
      boxes_.push_back(std::move(*built[k]));
      stress_[k] = boxes_[k].stress_gpa();
    }
  gradients_.assign(m, md::Mat3{});
  box_seconds_.assign(m, 0.0);
  rotation_.assign(p.size(), as_array(Mat3d::Identity()));
  md_seconds_ += seconds_since(t0);
  publish(p, failed, false, 0.0);
  atom_steps_ = static_cast<std::int64_t>(p.size()) * atoms_per_point() * cfg_.relax_steps;
}

template <int Dim>
void MdClosure<Dim>::update_stress(const Points<Dim>& p, double dt) {
  const std::size_t n = p.size(), first = spread_.begin(), m = spread_.count();
  const int steps = cfg_.md_steps(dt);
  if (steps == 0)
    throw InputError(fmt::format("md_closure: the continuum step ({} ps) is not a whole number of MD "
                                 "steps of {} ps",
                                 dt * cfg_.units.time_ps, cfg_.dt));
  const double dt_ps = dt * cfg_.units.time_ps;
  for (std::size_t k = 0; k < m; ++k)
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) gradients_[k][3 * a + b] = p.L(first + k, a, b) / cfg_.units.time_ps;  // 1/ps
  const bool consistent = cfg_.energy_consistency < 0 ? Dim > 1 : cfg_.energy_consistency == 1;
  std::optional<ranks::Failure> failed;
  std::vector<double> injected(consistent ? m : 0), short_of(consistent ? m : 0);
  const auto t0 = std::chrono::steady_clock::now();
  try {
    if (!consistent) {
      batch_.advance(boxes_, gradients_, steps, cfg_.dt, cfg_.sample, stress_, first, &box_seconds_);
    } else {
      // Eq. 7.11 per box, on the box's thread: the work of the stress the continuum used
      // this step on the point (the box's turned by R, plus the tensor viscous stress
      // where it is on; GPa) over the rate of deformation.
      constexpr double GPa_A3_in_eV = 1.0 / 160.21766208;  // 1 GPa x 1 A^3 in eV
      batch_.each_box(m, first, &box_seconds_, [&](std::size_t k) {
        const std::size_t q = first + k;
        md::System& box = boxes_[k];
        const Mat3d R = as_matrix(rotation_[q]);
        Mat3d sigma = R * as_matrix(stress_[k]) * R.transpose();
        for (int a = 0; a < Dim; ++a)
          for (int b = 0; b < Dim; ++b)
            if (p.viscous[a * Dim + b]) sigma(a, b) += p.viscous[a * Dim + b][q] * cfg_.units.stress_GPa;
        const Mat3d L = as_matrix(gradients_[k]);
        const double power = (sigma.array() * (0.5 * (L + L.transpose())).array()).sum();  // GPa/ps
        const double e0 = box.potential_energy() + box.thermal_kinetic_energy(), v0 = box.box().volume();
        multiscale::advance_box(box, gradients_[k], steps, cfg_.dt, cfg_.sample, stress_[k]);
        const double work = 0.5 * (v0 + box.box().volume()) * power * dt_ps * GPa_A3_in_eV;
        double add = work - (box.potential_energy() + box.thermal_kinetic_energy() - e0);
        const double room = box.thermal_kinetic_energy();
        if (add < -room) short_of[k] = -room - add, add = -room;
        box.add_energy(add);
        injected[k] = add;
      });
    }
  } catch (const std::exception& e) {
    failed = ranks::Failure{ranks::Failure::run, where() + e.what()};
  }
  md_seconds_ += seconds_since(t0);
  if (consistent) {  // collective; summed in point order: the same on any rank count
    std::vector<double> mine(2 * m);
    for (std::size_t k = 0; k < m; ++k) mine[2 * k] = injected[k], mine[2 * k + 1] = short_of[k];
    const std::vector<double> all = spread_.all(mine, 2);
    for (std::size_t q = 0; q < n; ++q) injected_ev_ += all[2 * q], shortfall_ev_ += all[2 * q + 1];
  }
  if constexpr (Dim > 1) {
    // R <- C(W dt) R C(W' dt)^T: the crystal turns with the point's spin W, the box's
    // with the spin W' its upper-triangular gradient keeps. Every point, on every rank.
    for (std::size_t q = 0; q < n; ++q) {
      md::Mat3 g{};
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) g[3 * a + b] = p.L(q, a, b) / cfg_.units.time_ps;
      if (md::is_upper_triangular(g)) continue;  // W' = W: R unchanged
      const Mat3d G = as_matrix(g), Gu = as_matrix(md::upper_triangular(g));
      const Mat3d W = 0.5 * (G - G.transpose()), Wb = 0.5 * (Gu - Gu.transpose());
      rotation_[q] = as_array(cayley(W, dt_ps) * as_matrix(rotation_[q]) * cayley(Wb, dt_ps).transpose());
    }
  }
  if (nan_point_ && spread_.owns(*nan_point_)) stress_[*nan_point_ - first][0] = std::nan("");
  publish(p, failed, true, dt);
  atom_steps_ += static_cast<std::int64_t>(n) * atoms_per_point() * steps;
}

// The point's stress: its box's, turned by the point's rotation (identity in 1-D).
template <int Dim>
void MdClosure<Dim>::set_point_stress(const Points<Dim>& p, std::size_t q) const {
  if constexpr (Dim == 1) {
    p.stress[0][q] = all_stress_[q][0] / cfg_.units.stress_GPa;
  } else {
    const Mat3d R = as_matrix(rotation_[q]);
    const Mat3d s = R * as_matrix(all_stress_[q]) * R.transpose();
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.sigma(q, a, b) = s(a, b) / cfg_.units.stress_GPa;
  }
}

template <int Dim>
void MdClosure<Dim>::publish(const Points<Dim>& p, std::optional<ranks::Failure> failed, bool strain, double dt) {
  const std::size_t first = spread_.begin(), m = spread_.count();
  std::vector<double> mine(m * kRecord, std::nan(""));
  for (std::size_t k = 0; k < m && !failed; ++k) {
    double* r = &mine[k * kRecord];
    for (int c = 0; c < 9; ++c) r[c] = stress_[k][c];
    const md::Box& b = boxes_[k].box();
    int i = 9;
    for (const double v : {b.lx, b.ly, b.lz, b.xy, b.xz, b.yz}) r[i++] = v;
    r[i] = static_cast<double>(boxes_[k].neighbor_builds());
    for (int c = 0; c < 9; ++c)
      if (!std::isfinite(stress_[k][c]))
        failed = ranks::Failure{ranks::Failure::run,
                                fmt::format("{}the MD box of material point {} gave a non-finite stress ({} GPa)",
                                            where(), first + k, stress_[k][c])};
  }
  const std::vector<double> all = spread_.all(mine, kRecord);
  if (const auto f = ranks::first_failure(failed)) {
    ranks::mark_agreed();
    ranks::raise(*f);
  }
  all_stress_.resize(p.size());
  neighbor_builds_ = 0;
  for (std::size_t q = 0; q < p.size(); ++q) neighbor_builds_ += static_cast<std::int64_t>(all[q * kRecord + 15]);
  const double l0 = cfg_.cells * props_.equilibrium.lattice_constant;
  for (std::size_t q = 0; q < p.size(); ++q) {
    for (int c = 0; c < 9; ++c) all_stress_[q][c] = all[q * kRecord + c];
    set_point_stress(p, q);
    if (!strain) continue;
    if constexpr (Dim == 1) {
      p.strain[0][q] = all[q * kRecord + 9] / l0 - 1.0;  // the box's engineering strain
    } else {
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.eps(q, a, b) += 0.5 * dt * (p.L(q, a, b) + p.L(q, b, a));
    }
  }
}

template <int Dim>
double MdClosure<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  return std::sqrt(modulus() / p.density(q));
}

template <int Dim>
void MdClosure<Dim>::save(std::ostream& out) const {
  std::ostringstream mine(std::ios::binary);
  for (const auto& b : boxes_) b.save(mine);
  const std::string all = ranks::gather_to_root(mine.str());  // System::save delimits each box
  if (!ranks::root()) return;
  const std::uint64_t n = spread_.points();
  write_raw(out, n);
  write_raw(out, atom_steps_);
  out.write(all.data(), static_cast<std::streamsize>(all.size()));
  // Eq. 7.11's tallies, every point's rotation and its box's last stress (the next
  // step's sigma^n): the same on every rank.
  write_raw(out, injected_ev_);
  write_raw(out, shortfall_ev_);
  for (const auto& r : rotation_) out.write(reinterpret_cast<const char*>(r.data()), sizeof(double) * 9);
  for (const auto& s : all_stress_) out.write(reinterpret_cast<const char*>(s.data()), sizeof(double) * 9);
}

template <int Dim>
void MdClosure<Dim>::load(std::istream& in) {
  // Each box takes far more than 64 bytes: the bound only keeps a damaged count from an
  // allocation; the box count is checked against the deck's points by the caller.
  const std::uint64_t n = read_count(in, 64, "md_closure boxes");
  read_raw(in, atom_steps_);
  if (!in) throw InputError("checkpoint: the MD boxes are truncated");
  spread_ = multiscale::Spread(n);
  boxes_.clear();
  boxes_.reserve(spread_.count());
  // Every box is read (the run's own figures follow them); this rank keeps its block.
  for (std::uint64_t q = 0; q < n; ++q) {
    try {
      md::System box = md::System::load(in, pot_, box_options());
      if (spread_.owns(q)) boxes_.push_back(std::move(box));
    } catch (const RunError& e) {  // a box the file describes that no run makes
      throw InputError(fmt::format("the MD box of point {}: {}", q, e.what()));
    }
  }
  read_raw(in, injected_ev_);
  read_raw(in, shortfall_ev_);
  rotation_.assign(n, md::Mat3{});
  all_stress_.assign(n, md::Mat3{});
  for (auto& r : rotation_) in.read(reinterpret_cast<char*>(r.data()), sizeof(double) * 9);
  for (auto& s : all_stress_) in.read(reinterpret_cast<char*>(s.data()), sizeof(double) * 9);
  if (!in) throw InputError("checkpoint: the MD boxes' rotations and stresses are truncated");
  gradients_.assign(spread_.count(), md::Mat3{});
  stress_.assign(all_stress_.begin() + static_cast<std::ptrdiff_t>(spread_.begin()),
                 all_stress_.begin() + static_cast<std::ptrdiff_t>(spread_.begin() + spread_.count()));
  box_seconds_.assign(spread_.count(), 0.0);
  if (const char* v = std::getenv("MPMX_TEST_NAN_POINT")) nan_point_ = std::strtoull(v, nullptr, 10);
}

template <int Dim>
bool MdClosure<Dim>::rebalance(double threshold) {
  if (ranks::size() == 1) return false;
  double mine = 0.0;
  for (double t : box_seconds_) mine += t;
  const double slowest = ranks::max({mine})[0], mean = ranks::sum(mine) / ranks::size();
  const std::vector<double> cost = spread_.all(box_seconds_, 1);
  box_seconds_.assign(box_seconds_.size(), 0.0);  // the next check measures afresh
  if (!(mean > 0.0) || slowest <= threshold * mean) return false;
  const multiscale::Spread next = multiscale::Spread::balanced(cost);
  if (next == spread_) return false;
  // Each box goes to the rank whose new block holds its point, as the checkpoint
  // writes it (state, neighbour list, random stream): the run goes on bit for bit.
  std::vector<std::ostringstream> out(static_cast<std::size_t>(ranks::size()));
  int to = 0;
  for (std::size_t k = 0; k < boxes_.size(); ++k) {
    const std::size_t q = spread_.begin() + k;
    while (q >= next.start(to + 1)) ++to;
    boxes_[k].save(out[static_cast<std::size_t>(to)]);
  }
  std::vector<std::string> bytes;
  for (auto& o : out) bytes.push_back(o.str());
  boxes_.clear();
  // What arrives is in the senders' rank order, that is in point order.
  std::istringstream in(ranks::exchange(bytes));
  spread_ = next;
  boxes_.reserve(spread_.count());
  for (std::size_t k = 0; k < spread_.count(); ++k) boxes_.push_back(md::System::load(in, pot_, box_options()));
  gradients_.assign(spread_.count(), md::Mat3{});
  stress_.assign(all_stress_.begin() + static_cast<std::ptrdiff_t>(spread_.begin()),
                 all_stress_.begin() + static_cast<std::ptrdiff_t>(spread_.begin() + spread_.count()));
  box_seconds_.assign(spread_.count(), 0.0);
  return true;
}

template <int Dim>
std::vector<material::Figure> MdClosure<Dim>::figures() const {
  const auto& eq = props_.equilibrium;
  return {{"md.atoms_per_point", std::int64_t{atoms_per_point()}},
          {"md.points", static_cast<std::int64_t>(spread_.points())},
          {"md.lattice_constant_A", eq.lattice_constant},
          {"md.energy_per_atom_eV", eq.energy_per_atom},
          {"md.c11_GPa", eq.c11_gpa},
          {"md.density", density()},
          {"md.energy_injected_eV", injected_ev_},  // eq. 7.11, running total
          {"md.energy_shortfall_eV", shortfall_ev_},
          {"md.neighbor_builds", neighbor_builds_}};
}

template class MdClosure<1>;
template class MdClosure<2>;
template class MdClosure<3>;

}  // namespace mpmx::multiscale
