#pragma once
// A grid convergence study: the deck run on `convergence.levels` grids, each with twice
// the cells per axis and half the time step of the one before (points per cell kept),
// each into DIR/level_K/; the observed order of each compared field is the least-squares
// slope of log(error) against log(dx) over the levels (VALIDATION.md N4).
#include <map>
#include <string>
#include <vector>

#include "mpmx/app/mpm/run.hpp"

namespace mpmx::app {

struct ConvergenceLevel {
  std::array<int, 3> cells{};
  double dx = 0.0, dt = 0.0;
  RunSummary run;
};

struct ConvergenceStudy {
  std::vector<ConvergenceLevel> levels;
  std::map<std::string, double> order_l2, order_l1;  // by field
};

// The config of level k (k = 0 is the deck's own grid).
MpmConfig refined(const MpmConfig& c, int k);

// Least-squares slope of log(e) over log(h); NaN with fewer than two positive errors.
double observed_order(const std::vector<double>& h, const std::vector<double>& e);

// Runs every level; writes DIR/run.json with convergence.levels and convergence.order.
ConvergenceStudy run_convergence(const MpmConfig& c, const RunOptions& o);

}  // namespace mpmx::app
