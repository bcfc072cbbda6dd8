#pragma once
// The all-atom flyer-on-rod run of an MD deck with a [rod] table (md/rod.hpp): the target
// equilibrated with the flyer held (velocities rescaled to the temperature every
// rod.rescale_every steps), then the flyer released at rod.flyer_velocity as a free rigid
// body, the region tracks recorded every analysis.every steps by the DPD run's own code
// (app/region_tracks.hpp), in the DPD deck's frame (flyer's first plane at x = 0). Writes
// thermo.csv (with the target's temperature and the flyer's velocity), tracks.csv,
// profile.csv, a LAMMPS dump every run.dump_every steps, and run.json's "rod" and
// "analysis" (onsets, wave speed) tables.
#include <string>

#include <toml++/toml.h>

#include "mpmx/app/md/checkpoint.hpp"
#include "mpmx/app/md/config.hpp"

namespace mpmx::app::md {

struct MdRunSummary;

// Runs it (or continues it from its checkpoint); returns "" or, when the state went
// non-finite, why the run stopped.
std::string run_rod(const MdConfig& c, const Potential& pot, const std::string& out_dir, MdRunSummary& r,
                    toml::table& rec, RunControl& control, bool quiet);

}  // namespace mpmx::app::md
