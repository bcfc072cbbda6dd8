#include "mpmx/material/md_closure.hpp"

#include <cmath>
#include <istream>
#include <optional>
#include <ostream>

#include <Eigen/Dense>
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
  r.c12 = eq.c12_gpa / u.stress_GPa;
  r.c44 = eq.c44_gpa / u.stress_GPa;
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

namespace {

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

}  // namespace

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

// The point's stress: the box's, turned by the point's rotation (identity in 1-D).
template <int Dim>
void MdClosure<Dim>::set_point_stress(const Points<Dim>& p, std::size_t q) const {
  if constexpr (Dim == 1) {
    p.stress[0][q] = stress_[q][0] / cfg_.units.stress_GPa;
  } else {
    const Mat3d R = as_matrix(rotation_[q]);
    const Mat3d s = R * as_matrix(stress_[q]) * R.transpose();
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) p.sigma(q, a, b) = s(a, b) / cfg_.units.stress_GPa;
  }
}

template <int Dim>
void MdClosure<Dim>::initialize(const Points<Dim>& p) {
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
  rotation_.assign(n, as_array(Mat3d::Identity()));
  stress_.resize(n);
  for (std::size_t q = 0; q < n; ++q) {
    stress_[q] = boxes_[q].stress_gpa();
    set_point_stress(p, q);
  }
  atom_steps_ = static_cast<std::int64_t>(n) * atoms_per_point() * cfg_.relax_steps;
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
  for (std::size_t q = 0; q < n; ++q)
    for (int a = 0; a < Dim; ++a)
      for (int b = 0; b < Dim; ++b) gradients_[q][3 * a + b] = p.L(q, a, b) / cfg_.units.time_ps;  // 1/ps
  const bool consistent = cfg_.energy_consistency < 0 ? Dim > 1 : cfg_.energy_consistency == 1;
  std::vector<double> injected(consistent ? n : 0), short_of(consistent ? n : 0);
  if (!consistent) {
    batch_.advance(boxes_, gradients_, steps, cfg_.dt, cfg_.sample, stress_);
  } else {
    // Eq. 7.11 per box, on the box's thread: the work of the stress the continuum used
    // this step (the box's at the start, in its frame) over the rate of deformation.
    constexpr double GPa_A3_in_eV = 1.0 / 160.21766208;  // 1 GPa x 1 A^3 in eV
    // The continuum's stress on the point this step, in the point's frame: the box's turned
    // by R, plus the artificial viscous stress where it is on (GPa).
    batch_.for_each(n, [&](std::size_t q) {
      md::System& box = boxes_[q];
      Mat3d sigma = as_matrix(rotation_[q]) * as_matrix(stress_[q]) * as_matrix(rotation_[q]).transpose();
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b)
          if (p.viscous[a * Dim + b]) sigma(a, b) += p.viscous[a * Dim + b][q] * cfg_.units.stress_GPa;
      const double e0 = box.potential_energy() + box.thermal_kinetic_energy();
      const md::Mat3 g = md::upper_triangular(gradients_[q]);  // the box's gradient (eq. 5.20)
      const Mat3d L = as_matrix(gradients_[q]);
      const double power = (sigma.array() * (0.5 * (L + L.transpose())).array()).sum();  // sigma : D, GPa/ps
      const double v0 = box.box().volume();
      multiscale::advance_box(box, g, steps, cfg_.dt, cfg_.sample, stress_[q]);
      const double v1 = box.box().volume();
      const double work = 0.5 * (v0 + v1) * power * dt_ps * GPa_A3_in_eV;
      const double change = box.potential_energy() + box.thermal_kinetic_energy() - e0;
      double add = work - change;
      const double room = box.thermal_kinetic_energy();
      if (add < -room) short_of[q] = -room - add, add = -room;
      box.add_energy(add);
      injected[q] = add;
    });
    for (std::size_t q = 0; q < n; ++q) injected_ev_ += injected[q], shortfall_ev_ += short_of[q];
  }
  if constexpr (Dim > 1) {
    // R <- C(W dt) R C(W' dt)^T: the crystal turns with the point's spin W, the box's
    // with the spin W' its upper-triangular gradient keeps.
    for (std::size_t q = 0; q < n; ++q) {
      if (md::is_upper_triangular(gradients_[q])) continue;  // W' = W: R unchanged
      const Mat3d G = as_matrix(gradients_[q]), Gu = as_matrix(md::upper_triangular(gradients_[q]));
      const Mat3d W = 0.5 * (G - G.transpose()), Wb = 0.5 * (Gu - Gu.transpose());
      rotation_[q] = as_array(cayley(W, dt_ps) * as_matrix(rotation_[q]) * cayley(Wb, dt_ps).transpose());
    }
  }
  const double l0 = cfg_.cells * props_.equilibrium.lattice_constant;
  for (std::size_t q = 0; q < n; ++q) {
    set_point_stress(p, q);
    if constexpr (Dim == 1) {
      p.strain[0][q] = boxes_[q].box().lx / l0 - 1.0;  // the box's engineering strain
    } else {
      for (int a = 0; a < Dim; ++a)
        for (int b = 0; b < Dim; ++b) p.eps(q, a, b) += 0.5 * dt * (p.L(q, a, b) + p.L(q, b, a));
    }
  }
  atom_steps_ += static_cast<std::int64_t>(n) * atoms_per_point() * steps;
}

template <int Dim>
double MdClosure<Dim>::sound_speed(const Points<Dim>& p, std::size_t q) const {
  return std::sqrt(modulus() / p.density(q));
}

template <int Dim>
void MdClosure<Dim>::save(std::ostream& out) const {
  const std::uint64_t n = boxes_.size();
  out.write(reinterpret_cast<const char*>(&n), sizeof n);
  out.write(reinterpret_cast<const char*>(&atom_steps_), sizeof atom_steps_);
  for (const auto& b : boxes_) b.save(out);
  {
    out.write(reinterpret_cast<const char*>(&injected_ev_), sizeof injected_ev_);
    out.write(reinterpret_cast<const char*>(&shortfall_ev_), sizeof shortfall_ev_);
    for (const auto& r : rotation_) out.write(reinterpret_cast<const char*>(r.data()), sizeof(double) * 9);
    for (const auto& s : stress_) out.write(reinterpret_cast<const char*>(s.data()), sizeof(double) * 9);
  }
}

template <int Dim>
void MdClosure<Dim>::load(std::istream& in) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  in.read(reinterpret_cast<char*>(&atom_steps_), sizeof atom_steps_);
  if (!in || n > (std::uint64_t{1} << 40)) throw InputError("checkpoint: the MD boxes are truncated or damaged");
  boxes_.clear();
  boxes_.reserve(n);
  for (std::uint64_t q = 0; q < n; ++q) boxes_.push_back(md::System::load(in, pot_, box_options()));
  gradients_.assign(n, md::Mat3{});
  stress_.assign(n, md::Mat3{});
  rotation_.assign(n, as_array(Mat3d::Identity()));
  {
    in.read(reinterpret_cast<char*>(&injected_ev_), sizeof injected_ev_);
    in.read(reinterpret_cast<char*>(&shortfall_ev_), sizeof shortfall_ev_);
    for (auto& r : rotation_) in.read(reinterpret_cast<char*>(r.data()), sizeof(double) * 9);
    for (auto& s : stress_) in.read(reinterpret_cast<char*>(s.data()), sizeof(double) * 9);
    if (!in) throw InputError("checkpoint: the MD boxes' rotations are truncated");
  }
}

template class MdClosure<1>;
template class MdClosure<2>;
template class MdClosure<3>;

}  // namespace mpmx::material
