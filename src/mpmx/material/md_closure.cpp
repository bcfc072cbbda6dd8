#include "mpmx/material/md_closure.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <istream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/md/lattice.hpp"

namespace mpmx::material {

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
  r.sound_speed = std::sqrt(r.modulus / r.density);
  return r;
}

// The record a point's box returns to every rank: its stress (GPa) and its box.
constexpr int kRecord = 15;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "rank r: " before a message where there are several ranks.
std::string where() { return ranks::size() > 1 ? fmt::format("rank {}: ", ranks::rank()) : ""; }

}  // namespace

MdClosureProperties md_closure_properties(const md::PotentialSpec& spec, const units::UnitSystem& u) {
  return properties(md::fcc_equilibrium(md::Potential(spec)), u);
}

int MdClosureConfig::md_steps(double dt_continuum) const {
  const double steps = dt_continuum * units.time_ps / dt;
  const long k = std::lround(steps);
  return k >= 1 && std::abs(steps - k) <= 1e-6 * steps ? static_cast<int>(k) : 0;
}

MdClosure::MdClosure(const MdClosureConfig& config)
    : cfg_(config), pot_(config.potential), props_(properties(md::fcc_equilibrium(pot_), config.units)),
      batch_(config.threads) {}

md::SystemOptions MdClosure::box_options() const {
  md::SystemOptions o;
  o.skin = cfg_.skin;
  o.mixed_precision = cfg_.mixed_precision;
  return o;
}

void MdClosure::initialize(const Points<1>& p) {
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
      } catch (const std::exception& e) {  // the same kind of error, naming the point
        ranks::Failure f = ranks::failure_of(e);
        f.message = fmt::format("the MD box of material point {}: {}", q, f.message);
        ranks::raise(f);
      }
    });
  } catch (const std::exception& e) {
    failed = ranks::failure_of(e);
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
  md_seconds_ += seconds_since(t0);
  publish(p, failed, false);
  atom_steps_ = static_cast<std::int64_t>(p.size()) * atoms_per_point() * cfg_.relax_steps;
}

void MdClosure::update_stress(const Points<1>& p, double dt) {
  const std::size_t n = p.size(), first = spread_.begin(), m = spread_.count();
  const int steps = cfg_.md_steps(dt);
  if (steps == 0)
    throw InputError(fmt::format("md_closure: the continuum step ({} ps) is not a whole number of MD "
                                 "steps of {} ps",
                                 dt * cfg_.units.time_ps, cfg_.dt));
  for (std::size_t k = 0; k < m; ++k) gradients_[k][0] = p.grad_v[0][first + k] / cfg_.units.time_ps;  // 1/ps
  std::optional<ranks::Failure> failed;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    batch_.advance(boxes_, gradients_, steps, cfg_.dt, cfg_.sample, stress_, first, &box_seconds_);
  } catch (const std::exception& e) {
    failed = ranks::Failure{ranks::Failure::run, where() + e.what()};
  }
  md_seconds_ += seconds_since(t0);
  if (nan_point_ && spread_.owns(*nan_point_)) stress_[*nan_point_ - first][0] = std::nan("");
  publish(p, failed, true);
  atom_steps_ += static_cast<std::int64_t>(n) * atoms_per_point() * steps;
}

void MdClosure::publish(const Points<1>& p, std::optional<ranks::Failure> failed, bool strain) {
  const std::size_t first = spread_.begin(), m = spread_.count();
  std::vector<double> mine(m * kRecord, std::nan(""));
  for (std::size_t k = 0; k < m && !failed; ++k) {
    double* r = &mine[k * kRecord];
    for (int c = 0; c < 9; ++c) r[c] = stress_[k][c];
    const md::Box& b = boxes_[k].box();
    int i = 9;
    for (const double v : {b.lx, b.ly, b.lz, b.xy, b.xz, b.yz}) r[i++] = v;
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
  const double l0 = cfg_.cells * props_.equilibrium.lattice_constant;
  for (std::size_t q = 0; q < p.size(); ++q) {
    p.stress[0][q] = all[q * kRecord] / cfg_.units.stress_GPa;
    if (strain) p.strain[0][q] = all[q * kRecord + 9] / l0 - 1.0;  // the box's engineering strain
  }
}

double MdClosure::sound_speed(const Points<1>& p, std::size_t q) const {
  return std::sqrt(modulus() / p.density(q));
}

void MdClosure::save(std::ostream& out) const {
  std::ostringstream mine(std::ios::binary);
  for (const auto& b : boxes_) b.save(mine);
  const std::string all = ranks::gather_to_root(mine.str());  // System::save delimits each box
  if (!ranks::root()) return;
  const std::uint64_t n = spread_.points();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(&atom_steps_), sizeof atom_steps_);
  out.write(all.data(), static_cast<std::streamsize>(all.size()));
}

void MdClosure::load(std::istream& in) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  in.read(reinterpret_cast<char*>(&atom_steps_), sizeof atom_steps_);
  if (!in) throw InputError("checkpoint: the MD boxes are truncated");
  spread_ = multiscale::Spread(n);
  boxes_.clear();
  boxes_.reserve(spread_.count());
  // Every box is read (the run's own figures follow them); this rank keeps its block.
  for (std::uint64_t q = 0; q < n; ++q) {
    md::System box = md::System::load(in, pot_, box_options());
    if (spread_.owns(q)) boxes_.push_back(std::move(box));
  }
  gradients_.assign(spread_.count(), md::Mat3{});
  stress_.assign(spread_.count(), md::Mat3{});
  box_seconds_.assign(spread_.count(), 0.0);
  if (const char* v = std::getenv("MPMX_TEST_NAN_POINT")) nan_point_ = std::strtoull(v, nullptr, 10);
}

bool MdClosure::rebalance(double threshold) {
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
  stress_.assign(spread_.count(), md::Mat3{});
  box_seconds_.assign(spread_.count(), 0.0);
  return true;
}

}  // namespace mpmx::material
