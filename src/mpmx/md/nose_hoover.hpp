#pragma once
// Temperature and pressure control: a Nose-Hoover chain thermostat and the
// Martyna-Tobias-Klein barostat with its own chain, integrated by the Trotter splitting
// of Tuckerman et al. (J. Phys. A 39, 5629, 2006) around the velocity-Verlet step, in
// the form of LAMMPS's fix nvt / npt / nph (Shinoda et al., PRB 69, 134103, 2004), so
// that a box prepared here and one prepared there sample the same ensemble. The
// barostat dilates an orthogonal box isotropically (one strain rate for all three axes,
// driven by the mean pressure) or per axis (each by its own normal stress).
#include <array>
#include <cstddef>
#include <vector>

#include "mpmx/md/system.hpp"

namespace mpmx::md {

struct NoseHooverOptions {
  bool thermostat = true;             // nvt, npt; off for nph
  double temperature = 300.0;         // K, the thermostat's target (and the barostat's kT)
  double t_damp = 0.1;                // ps, the thermostat's period (LAMMPS's Tdamp)
  bool barostat = false;              // npt, nph
  std::array<double, 3> pressure{};   // GPa, compression positive (LAMMPS's sign), per axis
  bool isotropic = true;              // one dilation for all axes, by the mean pressure
  std::array<bool, 3> axes{true, true, true};  // per axis (not isotropic): which dilate
  // Hugoniostat (LAMMPS's fix nphug, Ravelo et al., PRB 70, 014103, 2004): the
  // thermostat's target follows the Hugoniot's energy condition E - E0 = (P + P0)(V0 - V)/2
  // about the state the box starts in, P the pressure along the one dilating axis, so
  // that the box settles on the Hugoniot at the axis's target pressure.
  bool hugoniot = false;
  double p_damp = 1.0;                // ps, the barostat's period (Pdamp)
  int chain = 3;                      // thermostats in each chain (tchain, pchain)
};

class NoseHoover : public System::Coupling {
 public:
  // At the run's start: the barostat's kT (nph: of the temperature `s` has) and the
  // Hugoniot's reference state are taken from `s`.
  NoseHoover(const NoseHooverOptions& o, const System& s);
  // Resumed about a system of `atoms` atoms from what state() gave: nothing is taken from
  // the system again, so the run goes on as if never stopped.
  NoseHoover(const NoseHooverOptions& o, std::size_t atoms, const std::vector<double>& state);
  void initial(System& s, double dt) override;
  void remap(System& s, double dt) override;
  void final(System& s, double dt) override;
  // The Hugoniot's reference state (the box at the start): energy (eV), volume (A^3),
  // pressure along the dilating axis (eV/A^3).
  double e0() const { return e0_; }
  double v0() const { return v0_; }
  double p0() const { return p0_; }
  // Every variable the integration carries from step to step (the chains, the barostat,
  // kT, the Hugoniot's reference and target), for a checkpoint; state_size(o) numbers.
  std::vector<double> state() const;
  static std::size_t state_size(const NoseHooverOptions& o) { return 6 * static_cast<std::size_t>(o.chain) + 11; }

 private:
  NoseHooverOptions o_;
  double kt_ = 0, tdof_ = 0, natoms_ = 0, pdim_ = 3;
  double t_target_ = 0;         // K, the thermostat's target now (moves under `hugoniot`)
  double e0_ = 0, v0_ = 0, p0_ = 0;
  std::vector<double> eta_, eta_dot_, eta_dotdot_;  // thermostat chain
  std::vector<double> etap_, etap_dot_, etap_dotdot_, etap_mass_;  // the barostat's chain
  std::array<double, 3> omega_dot_{}, omega_mass_{};              // barostat (1/ps, eV ps^2)
  double mtk_term2_ = 0;

  NoseHoover(const NoseHooverOptions& o, std::size_t atoms);  // what both starts share
  void set_kt(double kt);  // kT and the barostat's masses, which follow from it
  void thermostat_chain(System& s, double dt);
  double eta_mass(int k, double kt) const;  // the thermostat chain's masses at kT
  void barostat_chain(double dt);
  void omega_force(const System& s, double dt);
  void v_press(System& s, double dt);
  double axis_pressure(const System& s) const;  // eV/A^3: the dilating axis's, or the mean
};

}  // namespace mpmx::md
