#pragma once
// A DPD configuration through LAMMPS, the peer of the cross-check and the bench: the
// system's particles as a LAMMPS data file (atom_style atomic, one type per mass,
// velocities), an input script with the same conservative pair potential (pair morse,
// pair nm/cut; the soft DPD force through pair python, since Debian's LAMMPS build has
// neither DPD-BASIC nor DPD-REACT), the same neighbour skin, and what it writes: the
// energy and the virial pressure tensor at step 0 in the log, the per-particle forces
// in a dump; optionally `steps` NVE steps for timing.
//
//   write_lammps_dpd(system, {.steps = 0}, "out/lammps");  // dpd.data, in.dpd (+ .py)
//   auto r = run_lammps_dpd("out/lammps");                  // lmp -in in.dpd
#include <array>
#include <string>
#include <vector>

#include "mpmx/dpd/system.hpp"

namespace mpmx::app::dpd {

using namespace mpmx::dpd;  // the DPD driver speaks the engine's names

struct LammpsDpdOptions {
  long steps = 0;          // NVE steps after step 0 (timing); 0: step 0 only
  double dt = 0.001;       // ps
  bool dump_forces = true;  // per-particle forces at step 0 (forces.dump)
  bool dump_final = false;  // positions and velocities after the steps (final.dump)
};

// Writes dir/dpd.data, dir/in.dpd and, for the soft force, dir/mpmx_soft_dpd.py.
// Needs one mass per type and no rigid group; throws InputError otherwise.
void write_lammps_dpd(const System& s, const LammpsDpdOptions& o, const std::string& dir);

struct LammpsDpdResult {
  double energy = 0;                 // eV at step 0
  std::array<double, 6> virial{};    // eV (xx, yy, zz, xy, xz, yz) at step 0, from the pressure tensor
  std::vector<long> id;              // per-particle forces at step 0, by id
  std::vector<double> fx, fy, fz;    // eV/Angstrom
  double loop_seconds = 0;           // LAMMPS's "Loop time" of the timed run (0 when steps = 0)
  // After the steps (dump_final): by id, positions wrapped into periodic axes.
  std::vector<long> final_id;
  std::vector<double> x, y, z, vx, vy, vz;
};

// Runs `lmp -in in.dpd` in dir and reads the results back. Throws RunError when lmp is
// missing or fails (naming the command, the exit status and the log's last lines).
LammpsDpdResult run_lammps_dpd(const std::string& dir);

// True when `lmp` is on PATH.
bool lammps_available();

}  // namespace mpmx::app::dpd
