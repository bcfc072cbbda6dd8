#pragma once
// The MD-to-DPD fit (seed 004 sec. 2.2, ref. [20]; VALIDATION.md D0): the conservative
// pair potential of mesoparticles of `atoms_per_particle` atoms on the coarse fcc
// lattice (constant a (atoms_per_particle)^(1/3), 2a for 8 atoms) fitted so that DPDE
// at the isotherm's temperature reproduces the MD isotherm P(rho).
//
// The form is Morse, U = D0 [exp(-2 alpha (r - r0)) - 2 exp(-alpha (r - r0))] shifted to
// zero at rc: a minimum (r0, D0) and a soft exponential core, three parameters that map
// onto the isotherm's zero-pressure density, its bulk modulus and the modulus's pressure
// derivative; an n-m form's power-law core is too stiff under the compression a
// mesoparticle of 8 atoms softens (and has one more parameter than the isotherm pins).
//
// The DPDE pressure is P_static(theta, a) + P_thermal(a): the perfect lattice's static
// pressure, exact and cheap for any parameters theta, plus the thermal part (the
// mesoparticles' kinetic pressure and vibrations). The fit iterates: least squares of
// P_static(theta, a_k) + c_k against P_MD(a_k) over theta (Nelder-Mead from the start
// parameters); then DPDE runs at the new theta measure c_k = P_DPDE - P_static; repeat.
// The last DPDE runs are the fitted model's isotherm. Deterministic: same inputs, same
// parameters (any thread count).
//
// Elastic targets (optional, issue "the MD-to-DPD bridge"): the isotherm pins the bulk
// modulus (C11 + 2 C12)/3, not the shear stiffness C11 - C12 a wave along a rod also
// needs. With them the objective adds weight n ((C11 - C11*)^2 + (C12 - C12*)^2) / (2 C*^2)
// (n the isotherm's points, C* the MD crystal's constants at the temperature, from
// strained boxes at its zero-pressure density); the model's constants are the Born
// lattice sums at the coarse lattice of that density plus a thermal part measured, like
// the pressure's, by DPDE strained boxes each round. Without them (the isotherm-only fit,
// the D0 deck) the objective and every number are as before.
#include <functional>
#include <optional>
#include <vector>

#include "mpmx/dpd/potential/morse.hpp"
#include "mpmx/multiscale/isotherm.hpp"
#include "mpmx/multiscale/strained_box.hpp"

namespace mpmx::multiscale {

struct ElasticTargets {
  bool on = false;
  double weight = 1.0;         // 0: measured and reported, not fitted
  double c11 = 0, c12 = 0;     // GPa, the MD crystal's at the temperature
  double lattice_constant = 0; // Angstrom, coarse: where the model's constants are taken
  StrainedBoxOptions boxes;    // the DPDE strained boxes (temperature, mass, gamma, C_v set by the fit)
};

// A fit between two rounds: all the next round starts from. A round is a function of it
// alone (its DPDE runs draw from the deck's seeds), so a fit resumed from one continues
// with the bits of a fit never stopped.
struct FitRound {
  int next = 0;                 // the round to run next (1..iterations)
  std::vector<double> theta;    // log D0, log alpha, log r0 after the last round's fit
  std::vector<double> thermal;  // GPa, the thermal pressure per density the next fit adds
  double thermal11 = 0, thermal12 = 0;  // GPa, the thermal part of C11 and C12
  int evaluations = 0;          // of the objective so far
};

struct FitOptions {
  double atoms_per_particle = 8;
  ElasticTargets elastic;
  dpd::MorsePotential start;  // initial parameters and the fixed cutoff / shift
  int iterations = 3;    // thermal-correction rounds (each a set of DPDE runs)
  // Called with each finished round but the last (rounds 0..iterations - 1), with what the
  // next starts from: for progress and checkpoints.
  std::function<void(const FitRound&)> on_round;
  std::optional<FitRound> resume_from;  // continue a stopped fit at resume_from->next
  DpdIsothermOptions dpd;
};

struct FitResult {
  dpd::MorsePotential potential;
  std::vector<double> md_lattice, coarse_lattice;  // Angstrom
  std::vector<IsothermPoint> md, dpd;              // the MD isotherm and the fitted DPDE one
  std::vector<double> static_pressure, thermal;    // GPa, at the fitted parameters
  double max_deviation_over_range = 0;  // max_k |P_DPDE - P_MD| / (max P_MD - min P_MD)
  int evaluations = 0;                  // of the least-squares objective, all rounds
  // With elastic targets: the fitted model's constants (GPa) at elastic.lattice_constant,
  // static (Born) and at the temperature (DPDE strained boxes of the last round).
  double born_c11 = 0, born_c12 = 0;
  CubicConstants dpd_constants;
};

// The DPDE strained boxes the fit measures the model's constants with: elastic.boxes's
// sizes, steps and seed, at the bath of the DPDE isotherm runs (o.dpd).
StrainedBoxOptions model_boxes(const FitOptions& o);

// `md` is the MD isotherm at the atomic lattice constants of its points.
FitResult fit_morse(const std::vector<IsothermPoint>& md, const FitOptions& o);

}  // namespace mpmx::multiscale
