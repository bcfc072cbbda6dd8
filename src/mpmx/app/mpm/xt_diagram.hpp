#pragma once
// sigma_xx over x and t, for the x-t diagram of a 1-D or quasi-1-D run (a shock's
// front, its reflections and releases as lines): every `every` steps (dt = "cfl" without
// it: at each 1/400 of the run's time, time_rows.hpp), the mean sigma_xx
// of the points in each grid cell along x (by their current x; NaN where a cell holds
// none) as one row of xt_sigma_xx.csv, whose header gives the cells' centres.
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

class Output;

template <int Dim>
class XtDiagram {
 public:
  XtDiagram(const MpmConfig& c, const mpm::Grid<Dim>& g);
  // After a step from t_before to s.time (at the start: t_before = s.time).
  void sample(const mpm::State<Dim>& s, double t_before, Output& out);

 private:
  std::int64_t every_;
  double interval_;  // > 0: rows by time
  std::string header_;
  std::vector<double> sum_, count_, row_;
};

}  // namespace mpmx::app
