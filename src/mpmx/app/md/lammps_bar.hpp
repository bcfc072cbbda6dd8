#pragma once
// The direct-MD bar (bar.hpp) through LAMMPS, so its reference can come from a cluster:
// the bar's exact state as a LAMMPS data file, an input script that integrates it as
// mpmx does (NVE, reflecting walls, no interaction across x) and writes the slab
// stress of eq. 2.25 exactly as slab_stress() defines it, a runner for `lmp`, and a
// reader that turns LAMMPS's output back into bar_stress.csv's table.
//
//   write_lammps_bar(bar, spec, dt, steps, every, "out/lammps");   // bar.data, in.bar
//   run_lammps("out/lammps", ranks);                               // lmp -in in.bar
//   auto s = read_lammps_bar_stress("out/lammps/bar_stress.lammps", dt, bins);
//   write_bar_stress_csv("out/bar_stress_lammps.csv", s, bar.slab_centres());
#include <cstdint>
#include <string>
#include <vector>

#include "mpmx/md/bar.hpp"
#include "mpmx/md/potential/potential.hpp"
#include "mpmx/particles/oriented_lattice.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

// Files inside the LAMMPS folder.
inline constexpr const char* kLammpsBarData = "bar.data";
inline constexpr const char* kLammpsBarInput = "in.bar";
inline constexpr const char* kLammpsBarStress = "bar_stress.lammps";  // fix ave/time, GPa
inline constexpr const char* kLammpsBarLog = "log.lammps";

// Writes dir/bar.data (the bar's current atoms, velocities, box and masses) and
// dir/in.bar (steps of dt ps, slab stress every `every` steps into bar_stress.lammps,
// step 0 included). Needs fixed walls (LAMMPS's wall/reflect mirrors v -> -v, mpmx's
// moving piston 2 v_w - v) and an eam or lj potential; throws InputError otherwise.
void write_lammps_bar(const Bar& bar, const PotentialSpec& spec, double dt, std::int64_t steps,
                      std::int64_t every, const std::string& dir);

// Shared with the jet route (lammps_jet.hpp). pair_style and pair_coeff lines for the
// potential mpmx uses, as its registry entry writes them (eam setfl, fs, funcfl; lj);
// InputError for the others.
std::string lammps_pair_lines(const PotentialSpec& spec, const Potential& pot);
// LAMMPS's `lattice` command of the crystal: `lattice STYLE a orient x u v w orient y ...
// orient z ...` (hcp off the ideal c/a as `lattice custom` with LAMMPS's hcp basis), which
// builds the sites particles::oriented_crystal does.
std::string lammps_lattice_line(const particles::LatticeSpec& spec);
// The system's atoms (positions in the box, on-step velocities), box and masses as a
// LAMMPS data file (atom_style atomic; a tilted box with its xy xz yz line); `title`
// goes into its first line.
void write_lammps_data(const System& sys, const std::string& path, const std::string& title);

struct LammpsRun {
  std::string command;  // as run, in `dir`
  int ranks = 1;        // 1 when mpirun was asked for but is not installed
};

// Runs `lmp -in INPUT` (in.bar unless told) in `dir` (under `mpirun -np ranks` when ranks > 1 and mpirun is
// on PATH). Throws RunError naming the command, its exit status and the end of
// log.lammps when lmp is missing or fails.
LammpsRun run_lammps(const std::string& dir, int ranks = 1, const std::string& input = kLammpsBarInput,
                     const std::string& output = kLammpsBarStress);

// One output step of the slab stress: `bins` tensors (GPa, Cauchy sign, row-major).
struct BarStressSample {
  std::int64_t step = 0;
  double time_ps = 0;
  std::vector<Mat3> stress_gpa;
};

// Parses the fix ave/time file in.bar writes; throws InputError naming the file, line
// and what was expected (a block with other than `bins` rows, a malformed number).
std::vector<BarStressSample> read_lammps_bar_stress(const std::string& path, double dt, int bins);

// The long table of bar_stress.csv (step,time_ps,bin,x_A,sxx_GPa,...,syz_GPa).
void write_bar_stress_csv(const std::string& path, const std::vector<BarStressSample>& samples,
                          const std::vector<double>& slab_centres);

}  // namespace mpmx::app::md
