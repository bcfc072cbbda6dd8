#pragma once
// The binned stress maps of a direct-MD jet run (`mpmx md` with a [jet] table: its
// md_bins.pvd lists the records, bins/md_bins_STEP.csv holds each record's bins, run.json
// the sample's geometry): the reference of the 2-D multiscale jet (VALIDATION.md J2-J4),
// each material point against the bin that holds it (eq. 7.12).
#include <string>
#include <vector>

namespace mpmx::reference {

class JetHistory {
 public:
  // DIR is the direct-MD run's output folder; throws InputError naming the file and line.
  static JetHistory read(const std::string& dir);

  double last_time_ps() const { return times_.empty() ? 0.0 : times_.back(); }
  // True when a record lies within half a record interval of t (ps).
  bool has(double t_ps) const;
  // The x of the piston's face (Angstrom, MD frame): the continuum's wall.
  double piston_face_A() const { return piston_face_; }
  // sxx (GPa) of the bin holding (x, y) (Angstrom, MD frame; y periodic) at the record
  // nearest t (ps); NaN outside the bins or in an empty bin.
  double sxx(double t_ps, double x_A, double y_A) const;

 private:
  std::size_t nearest(double t_ps) const;
  std::vector<double> times_;               // ps, increasing
  std::vector<std::vector<double>> sxx_;    // [record][ix + nx iy], GPa (NaN: no atoms)
  int nx_ = 0, ny_ = 0;
  double x0_ = 0.0, dx_ = 1.0, dy_ = 1.0, piston_face_ = 0.0;
  std::string dir_;
};

}  // namespace mpmx::reference
