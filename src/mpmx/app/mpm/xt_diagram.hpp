#pragma once
// sigma_xx over x and t, for the x-t diagram of a 1-D or quasi-1-D run (a shock's
// front, its reflections and releases as lines): every `every` steps, the mean sigma_xx
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
  void sample(const mpm::State<Dim>& s, Output& out);

 private:
  std::int64_t every_;
  std::string header_;
  std::vector<double> sum_, count_, row_;
};

}  // namespace mpmx::app
