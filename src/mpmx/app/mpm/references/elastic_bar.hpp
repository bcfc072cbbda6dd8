#pragma once
// A solution of the elastic bar (standing wave, wave reflection) as a field reference.
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

#include "mpmx/app/mpm/reference.hpp"
#include "mpmx/reference/standing_wave.hpp"
#include "mpmx/reference/wave_reflection.hpp"

namespace mpmx::app {

template <class Solution>
class ElasticBar final : public Reference {
 public:
  ElasticBar(Solution w, double t_end) : w_(w), t_end_(t_end) {}
  const std::vector<std::string>& fields() const override { return fields_; }
  bool valid(double t) const override { return t <= t_end_ * (1 + 1e-12); }
  double value(const std::string& f, double x, double t) const override {
    if (f == "velocity") return reference::velocity(w_, x, t);
    if (f == "strain") return reference::strain(w_, x, t);
    if (f == "stress") return reference::stress(w_, x, t);
    return reference::density(w_, x, t);
  }
  double baseline(const std::string& f) const override { return f == "density" ? w_.rho0 : 0.0; }
  double total_energy(double t) const override {
    if constexpr (std::is_same_v<Solution, reference::WaveReflection>)
      return valid(t) ? reference::total_energy(w_, t) : std::nan("");
    return std::nan("");
  }

 private:
  Solution w_;
  double t_end_;
  std::vector<std::string> fields_{"velocity", "strain", "stress", "density"};
};

}  // namespace mpmx::app
