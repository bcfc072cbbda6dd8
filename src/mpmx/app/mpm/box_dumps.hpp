#pragma once
// output.md_dump: the MD boxes of chosen material points as LAMMPS text dumps that OVITO
// reads, DIR/md_dump/point_<q>_<step>.dump (one frame a file: a sequence OVITO opens by
// the pattern point_<q>_*.dump, and a resumed run rewrites the frames it takes again).
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/material/material.hpp"
#include "mpmx/mpm/state.hpp"

namespace mpmx::app {

template <int Dim>
class BoxDumps {
 public:
  // `fields`: per-atom columns after the positions and velocities (md/lammps_dump.hpp).
  BoxDumps(const std::string& dir, std::vector<std::int64_t> points, std::vector<std::string> fields,
           const material::Material<Dim>& law);
  // The boxes of the points at the state's step. Collective under MPI; rank 0 writes.
  void write(const mpm::State<Dim>& s) const;

 private:
  std::string dir_;
  std::vector<std::int64_t> points_;
  std::vector<std::string> fields_;
};

}  // namespace mpmx::app
