#pragma once
// The deck's [[gauge]]s over a run: each picks its material points once, from the
// initial state (the point nearest `at`; the outermost points of a body's face), and
// records a row every `every` steps: time, place, velocity, stress and density of the
// point, or the mean place and velocity of the face's points. Rows go to
// gauge_<name>.csv (through Output, so that a resumed run continues its table) and, for
// a run without a folder (tests, the library), into memory.
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/app/mpm/config.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

class Output;

// One gauge's history: its columns and its rows.
struct GaugeTrace {
  std::string name;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  // The column of that name (its index), or -1.
  int column(const std::string& c) const;
};

template <int Dim>
class Gauges {
 public:
  // `initial`: the run's state as its deck places it (before any checkpoint is loaded).
  Gauges(const MpmConfig& c, const mpm::State<Dim>& initial, bool keep_rows);
  // A row for each gauge due at this step.
  void sample(const mpm::State<Dim>& s, Output* out);
  const std::vector<GaugeTrace>& traces() const { return traces_; }
  bool empty() const { return gauges_.empty(); }
  // The points a gauge follows (one for a point gauge), for checks and messages.
  const std::vector<std::size_t>& points(std::size_t gauge) const { return points_[gauge]; }

 private:
  std::vector<GaugeConfig> gauges_;
  std::vector<std::vector<std::size_t>> points_;
  std::vector<GaugeTrace> traces_;
  std::vector<std::string> headers_;
  bool keep_rows_;
  std::vector<double> row_;
};

}  // namespace mpmx::app
