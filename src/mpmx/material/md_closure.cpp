#include "mpmx/material/md_closure.hpp"

#include <cmath>
#include <istream>
#include <optional>
#include <ostream>

#include <fmt/format.h>

#include "mpmx/core/error.hpp"
#include "mpmx/io/checked_file.hpp"
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
  const std::size_t n = p.size();
  const double a0 = props_.equilibrium.lattice_constant;
  // Each point's box built on the threads (section 6.2), then kept in point order.
  std::vector<std::optional<md::System>> built(n);
  batch_.for_each(n, [&](std::size_t q) {
    md::System box(md::fcc(cfg_.cells, cfg_.cells, cfg_.cells, a0, p.strain[0][q]), pot_, box_options());
    if (cfg_.temperature > 0) box.thermalize(cfg_.temperature, cfg_.seed, q);
    box.advance(static_cast<int>(cfg_.relax_steps), cfg_.dt);  // zero strain rate
    built[q].emplace(std::move(box));
  });
  boxes_.clear();
  boxes_.reserve(n);
  for (auto& b : built) boxes_.push_back(std::move(*b));
  gradients_.assign(n, md::Mat3{});
  stress_.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    stress_[q] = boxes_[q].stress_gpa();
    p.stress[0][q] = stress_[q][0] / cfg_.units.stress_GPa;
  }
  atom_steps_ = static_cast<std::int64_t>(n) * atoms_per_point() * cfg_.relax_steps;
}

void MdClosure::update_stress(const Points<1>& p, double dt) {
  const std::size_t n = p.size();
  const int steps = cfg_.md_steps(dt);
  if (steps == 0)
    throw InputError(fmt::format("md_closure: the continuum step ({} ps) is not a whole number of MD "
                                 "steps of {} ps",
                                 dt * cfg_.units.time_ps, cfg_.dt));
  for (std::size_t q = 0; q < n; ++q) gradients_[q][0] = p.grad_v[0][q] / cfg_.units.time_ps;  // 1/ps
  batch_.advance(boxes_, gradients_, steps, cfg_.dt, cfg_.sample, stress_);
  const double l0 = cfg_.cells * props_.equilibrium.lattice_constant;
  for (std::size_t q = 0; q < n; ++q) {
    p.stress[0][q] = stress_[q][0] / cfg_.units.stress_GPa;
    p.strain[0][q] = boxes_[q].box().lx / l0 - 1.0;  // the box's engineering strain
  }
  atom_steps_ += static_cast<std::int64_t>(n) * atoms_per_point() * steps;
}

double MdClosure::sound_speed(const Points<1>& p, std::size_t q) const {
  return std::sqrt(modulus() / p.density(q));
}

void MdClosure::save(std::ostream& out) const {
  const std::uint64_t n = boxes_.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(&atom_steps_), sizeof atom_steps_);
  for (const auto& b : boxes_) b.save(out);
}

void MdClosure::load(std::istream& in) {
  // Each box takes far more than 64 bytes: the bound only keeps a damaged count from an
  // allocation; the box count is checked against the deck's points by the caller.
  const std::uint64_t n = io::read_count(in, 64, "md_closure boxes");
  in.read(reinterpret_cast<char*>(&atom_steps_), sizeof atom_steps_);
  if (!in) throw InputError("checkpoint: the MD boxes are truncated");
  boxes_.clear();
  boxes_.reserve(n);
  for (std::uint64_t q = 0; q < n; ++q) {
    try {
      boxes_.push_back(md::System::load(in, pot_, box_options()));
    } catch (const RunError& e) {  // a box the file describes that no run makes
      throw InputError(fmt::format("the MD box of point {}: {}", q, e.what()));
    }
  }
  gradients_.assign(n, md::Mat3{});
  stress_.assign(n, md::Mat3{});
}

}  // namespace mpmx::material
