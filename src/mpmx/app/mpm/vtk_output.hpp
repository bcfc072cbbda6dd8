#pragma once
// The VTK files of a run for ParaView: DIR/vtk/particles_NNNNNN.vtu (every particle
// field; stress, strain and grad v as tensors) and DIR/vtk/grid_NNNNNN.vti (nodal mass
// and velocity) at each record, listed with their times in DIR/particles.pvd and
// DIR/grid.pvd. Beside the fields: the point's id, body and material, and the law's own
// fields (material::PointField).
#include <string>

#include "mpmx/io/vtk.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

template <int Dim>
class VtkOutput {
 public:
  // `resume_time` >= 0: a resumed run keeps the series' records up to that time.
  VtkOutput(const std::string& dir, double resume_time);
  // `final`: a stopped run's last state, vtk/particles_final_NNNNNN.vtu (and grid_final_),
  // listed last in the series.
  void record(const mpm::State<Dim>& s, bool final = false);

 private:
  std::string dir_;
  io::vtk::Series particles_, grid_;
};

}  // namespace mpmx::app
