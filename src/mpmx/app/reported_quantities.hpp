#pragma once
// Every figure a run reports (thermo rows, run.json) finite, or the run stops (exit 3)
// naming the first that is not, its step and time: a temperature of `inf` in a table and
// `null` in run.json is a silently wrong result, not a result.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace mpmx::app {

struct Reported {
  std::string_view name;  // with its unit: "temperature (K)"
  double value;
};

// "" when every value is finite; else "step N (t = T ps): NAME is VALUE: the state went
// non-finite (...)" for the first that is not. `time_unit` names the time ("ps").
inline std::string first_non_finite(std::int64_t step, double time, std::string_view time_unit,
                                    std::initializer_list<Reported> figures) {
  for (const Reported& f : figures)
    if (!std::isfinite(f.value))
      return fmt::format("step {} (t = {} {}): {} is {}: the state went non-finite (the time step, the "
                         "deformation or an input may be wrong)",
                         step, time, time_unit, f.name, f.value);
  return {};
}

}  // namespace mpmx::app
