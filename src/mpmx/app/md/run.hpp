#pragma once
// Runs an MD-only deck: builds the crystal, thermalises it, advances it (optionally
// under a velocity gradient) and writes DIR/run.json and DIR/thermo.csv; or the deck's
// bar or jet. Ctrl-C or SIGTERM stops it at the next record with a checkpoint
// (run_control.hpp), from which --resume continues bit-for-bit.
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "mpmx/app/md/config.hpp"
#include "mpmx/app/md/checkpoint.hpp"

namespace mpmx::app::md {

using namespace mpmx::md;  // the MD driver speaks the engine's names

struct MdRunSummary {
  long atoms = 0;
  long steps = 0;        // the run's, those before a --resume included
  long steps_now = 0;    // this invocation's, which wall_seconds and the rate are of
  double wall_seconds = 0;
  double atom_steps_per_second = 0;
  double potential_energy_per_atom = 0;
  Mat3 stress_gpa{};
  bool interrupted = false;  // stopped on Ctrl-C, SIGTERM or stop_after: a checkpoint written
  std::int64_t step = 0, last_step = 0;  // the system's step where it ended, and the deck's last
  std::vector<std::string> notes;        // lines for the terminal after the summary ([elastic]'s)
};

// run.json's "tile_A" of a [jet] or [rod]: the lattice's periodic tile (Angstrom) at
// `constant`, what their cell counts count.
toml::array tile_lengths(particles::LatticeSpec lattice, double constant);

MdRunSummary run_md(const MdConfig& config, const std::string& out_dir, const toml::table& deck_echo,
                    const RunControlOptions& options = {});

}  // namespace mpmx::app::md
