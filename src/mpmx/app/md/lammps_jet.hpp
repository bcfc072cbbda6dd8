#pragma once
// The direct-MD jet (jet.hpp) through LAMMPS, which is also how the full size runs on a
// cluster: the sample's exact atoms and velocities as a data file (piston atoms first,
// ids 1..piston_atoms), an input script that holds the piston at rest (fix nve on the
// rest only), keeps x periodic over the same vacuum mpmx has, and writes the stress of
// eq. 2.25 on the same nx x ny bins exactly as bin_fields() defines it.
//
//   write_lammps_jet(sys, geometry, grid, spec, dt, steps, every, "out/lammps");  // jet.data, in.jet
//   run_lammps("out/lammps", ranks, kLammpsJetInput, kLammpsJetStress);
//   auto s = read_lammps_bar_stress("out/lammps/jet_stress.lammps", dt, nx * ny);
#include <cstdint>
#include <string>

#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/jet.hpp"
#include "mpmx/md/potential/potential.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

inline constexpr const char* kLammpsJetData = "jet.data";
inline constexpr const char* kLammpsJetInput = "in.jet";
inline constexpr const char* kLammpsJetStress = "jet_stress.lammps";  // fix ave/time, GPa, per bin

// Writes dir/jet.data and dir/in.jet: `steps` of dt ps, the bins' stress every `every`
// steps (step 0 included) into jet_stress.lammps, a dump every `dump_every` (0: none).
void write_lammps_jet(const System& sys, const JetGeometry& geometry, const BinGrid& grid,
                      const PotentialSpec& spec, double dt, std::int64_t steps, std::int64_t every,
                      std::int64_t dump_every, const std::string& dir);

}  // namespace mpmx::app::md
