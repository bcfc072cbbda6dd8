#pragma once
// The direct-MD jet run of an MD deck with a [jet] table (jet.hpp): binned fields per
// record (DIR/bins/md_bins_STEP.csv in Angstrom, DIR/vtk/md_bins_STEP.vti in nm and
// DIR/md_bins.pvd for ParaView), the y-pooled profile along x (jet_profile.csv), the shock front per record
// (jet_front.csv), thermo.csv, a LAMMPS dump every run.dump_every steps, and the
// figures run.json takes: the lab-frame shock speed and the peak compression.
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/md/config.hpp"
#include "mpmx/app/md/checkpoint.hpp"
#include "mpmx/md/bins2d.hpp"
#include "mpmx/md/jet.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

struct MdRunSummary;

// The shock front: the first column from the piston's face whose mean x-velocity has
// dropped below -up/2 (shocked copper is at rest in the lab, the block at -up),
// interpolated linearly between column centres; NaN when no column is shocked yet.
double shock_front(const BinFields& columns, double piston_face, double up_A_ps);

// Lab-frame shock speed (Angstrom/ps) from a least-squares line through (t, front)
// for the records while the front lies between the piston face and the notch tip
// (tip(t) = tip0 - up t) with a column to spare each side; NaN with fewer than 3.
double shock_speed(const std::vector<double>& t, const std::vector<double>& front, double piston_face,
                   double notch_tip0, double up_A_ps, double column_width);

// Runs it (or, on a resumed run, continues it from its checkpoint); returns "" or, when
// the state went non-finite, why the run stopped.
std::string run_jet(const MdConfig& c, const Potential& pot, const std::string& out_dir, MdRunSummary& r,
                    toml::table& rec, RunControl& control, bool quiet);

// The grid of bins over a jet sample: nx x ny over [x0, x0 + length) x [0, ly).
BinGrid jet_grid(const JetGeometry& g, int nx, int ny);

}  // namespace mpmx::app::md
