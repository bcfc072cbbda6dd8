#pragma once
// The binned stress history of a direct-MD bar (bar_stress.csv of `mpmx md` with a
// [bar] table, or the same table read back from LAMMPS): the reference of the 1-D
// multiscale cases, and the error of eq. 7.12 against it.
#include <string>
#include <vector>

namespace mpmx::reference {

class BarHistory {
 public:
  // Reads step,time_ps,bin,x_A,sxx_GPa,... rows; throws InputError naming the file and line.
  static BarHistory read(const std::string& path);

  int bins() const { return bins_; }
  double last_time_ps() const { return times_.empty() ? 0.0 : times_.back(); }
  // True when a record lies within half a record interval of t (ps).
  bool has(double t_ps) const;
  // sxx (GPa) of the bin holding the fraction xi in [0, 1] of the bar, at the record
  // nearest t (ps).
  double sxx(double t_ps, double xi) const;

 private:
  std::size_t nearest(double t_ps) const;
  std::vector<double> times_;              // ps, increasing
  std::vector<std::vector<double>> sxx_;   // [record][bin], GPa
  int bins_ = 0;
  std::string path_;
};

// Eq. 7.12: sqrt(sum (s_md - s_ms)^2 / sum s_md^2) over material points, each against
// the direct-MD bin it lies in.
struct Eq712 {
  double squared_difference = 0.0, squared_reference = 0.0;
  void add(double ms, double md) {
    squared_difference += (md - ms) * (md - ms);
    squared_reference += md * md;
  }
  double value() const;
};

}  // namespace mpmx::reference
