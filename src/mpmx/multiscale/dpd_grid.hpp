#pragma once
// DPD particles on the MPM background grid (seed 004 sec. 3.2, steps s1-s14): the
// "DPD/MPM-grid" model, and with continuum points the concurrent DPD/MPM model of
// eq. 3.1. Each step, after the system's stochastic sweep:
//
//   s1-s2   node mass and momentum from every moving particle, trilinear N_i(x_p);
//   s3b     DPD particles: their pair forces F_p (conservative; the sweep gave the
//           dissipative and random impulses) into the nodes, F_p N_i;
//   s3a     continuum points: -G_i . sigma_p V_p (eq. 3.1 adds the two at the interface),
//           and with the pair reaction (the default) the pair forces of their DPD
//           neighbours, F_p N_i: Newton's third law for eq. 3.2's forces, which the seed's
//           eq. 3.1 leaves out (without it the interface reflects the wave, D3);
//   s5      nodal momentum += dt f_i;
//   s6-s8   a_p = sum f_i / m_i N_i, v_p += dt a_p, x_p += dt sum (m v)_i / m_i N_i;
//   s10-s14 continuum points only: momenta re-mapped, L_p = sum v_i G_i, volume and
//           stress by their law (any Material<3>).
//
// A node whose mass is below 1e-12 of a particle's (machine precision, the seed's rule)
// is left out of s6-s8 and s11. Rigid particles (flyer, grips) move at their velocity and
// are not mapped: they act through the DPD particles' pair forces. The DPD particles in
// the interface feel the continuum points within their cutoff as DPD neighbours (eqs.
// 3.2-3.4: pair forces, and the sweep with the points as particles of infinite mass).
//
// The grid is fixed: cubic cells of edge h over a box that must hold every moving
// particle for the whole run (a particle leaving it stops the run, named).
// Results do not depend on the thread count: the scatter is serial, the gathers write
// per particle.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "mpmx/dpd/mover.hpp"
#include "mpmx/material/material.hpp"
#include "mpmx/material/points.hpp"
#include "mpmx/mpm/grid.hpp"
#include "mpmx/particles/box.hpp"

namespace mpmx::multiscale {

class DpdGrid final : public dpd::Mover {
 public:
  // Cells of edge `cell` (Angstrom) covering [lo, hi] (rounded out to whole cells).
  DpdGrid(double cell, const particles::Vec3& lo, const particles::Vec3& hi, int threads = 1);

  // The particles of external group `group` become continuum points of density
  // mass / volume_per_point with their stress from `law` (stress in eV/Angstrom^3).
  void set_continuum(int group, std::unique_ptr<material::Material<3>> law, const dpd::Particles& p,
                     double volume_per_point);

  void move(dpd::Particles& p, double dt) override;
  void report(toml::table& out) const override;
  void save(std::ostream& out) const override;
  void load(std::istream& in) override;
  // Whether the continuum points take the reaction of their DPD neighbours' pair forces
  // (default) or only their stress, as eq. 3.1 is written.
  void set_pair_reaction(bool on) { reaction_ = on; }
  // The continuum law's constants, for the record (GPa).
  void set_constants_gpa(double c11, double c12, double c44) { constants_ = {c11, c12, c44}; }

  const mpm::Grid<3>& grid() const { return g_; }
  std::int64_t skipped_nodes() const { return skipped_; }  // node-steps left out (small mass)
  std::size_t continuum_points() const { return cont_id_.size(); }
  // Continuum point k's stress component [a * 3 + b] (eV/Angstrom^3), by particle id.
  double continuum_stress(std::int64_t id, int component) const;

 private:
  struct Stencil {
    std::size_t base = 0;     // storage index of the cell's lowest node
    std::array<double, 3> f;  // position in the cell, 0..1 per axis
  };
  void make_grid(const std::array<double, 3>& lower, const std::array<double, 3>& upper,
                 const std::array<int, 3>& cells);
  void locate(const dpd::Particles& p);
  double corner(const Stencil& s, int k, double G[3]) const;
  material::Points<3> points();
  void update_continuum(dpd::Particles& p, double dt);

  mpm::Grid<3> g_;
  std::array<std::size_t, 8> off_{};  // storage offsets of a cell's 8 corners
  int threads_ = 1;
  std::int64_t skipped_ = 0;
  double m_eps_ = 0;  // this step's near-zero node mass
  std::vector<Stencil> st_;         // per particle (mobile and continuum)
  std::vector<std::uint8_t> moves_;  // 1 mobile DPD, 2 continuum, 0 rigid
  std::vector<double> node_acc_[3];
  std::vector<std::uint8_t> touched_;  // per node: in active_
  std::vector<std::size_t> active_;    // the nodes this step's particles touch

  // Continuum points, by slot; slot_of_id_ finds a particle's slot after the system's sorts.
  int cont_group_ = -100;
  std::array<double, 3> constants_{};
  bool reaction_ = true;
  std::unique_ptr<material::Material<3>> law_;
  std::vector<std::int64_t> cont_id_;
  std::vector<std::int32_t> slot_of_id_;
  std::vector<double> mass_, volume_, volume0_, length_;
  std::array<std::vector<double>, 9> grad_v_, stress_, strain_;
};

}  // namespace mpmx::multiscale
