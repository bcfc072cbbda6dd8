#pragma once
// Runs a fit-dpd deck (D0): the MD isotherm, the fit, the fitted DPDE isotherm; writes
// DIR/isotherm.csv, DIR/<potential file> and DIR/run.json (parameters, the largest
// deviation over the MD pressure range, zero-pressure densities, D0's targets; with
// [elastic] the MD crystal's and the model's C11, C12 and <100> bar speeds).
#include <functional>
#include <string>

#include <toml++/toml.h>

#include "mpmx/app/dpd/fit_checkpoint.hpp"
#include "mpmx/app/dpd/fit_config.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

struct FitRunSummary {
  MorsePotential potential;
  double max_deviation_over_range = 0;
  double zero_pressure_md = 0, zero_pressure_dpd = 0;  // rho / rho0
  bool elastic = false;                                // [elastic]: the constants' residuals
  double c11_residual = 0, c12_residual = 0;           // (DPDE - MD) / MD at the temperature
  double wall_seconds = 0;
};

// `quiet`: no progress line. `from`: the stages a stopped fit finished (empty: a fresh fit); `keep` is given the
// stages finished so far after each (for the checkpoint a signal writes).
FitRunSummary run_fit(const FitConfig& c, const std::string& out_dir, const toml::table& deck_echo, int threads,
                      bool quiet = false, const FitProgress& from = {}, const std::function<void(const FitProgress&)>& keep = {});

}  // namespace mpmx::app::dpd
